package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsTransform;
import rp1.rossum.request.RsPainterChangeRequest;

/** Paint trails (behavior.md section 9): spacing, segments, erasure. */
class PaintTrailTest {
    private final RsBodyPainter painter = new RsBodyPainter(new double[] {0, 0, 0.1, 0, 0.1, 0.1}, 3);

    private RsPainterChangeRequest activate(double width, Color... colors) {
        return new RsPainterChangeRequest(painter.getID(), false, true, true, 0.0, 0.0, width, colors);
    }

    private static void moveTo(PaintTrail t, double x, int series) {
        t.record(new RsTransform(0.0, x, 0.0), series);
    }

    @Test
    void pointsCloserThanOneCentimetreToTheLastAreSkipped() {
        PaintTrail t = new PaintTrail(painter);
        t.apply(activate(0.02, Color.red));
        for (int i = 0; i <= 10; i++) {
            moveTo(t, 0.004 * i, 1);
        }
        TrailSegment s = t.getSegments().get(0);
        assertEquals(4, s.getCount(), "0, 0.012, 0.024, 0.036: every third 4 mm step");
        assertEquals(0.012, s.getX(1), 1e-7);
    }

    @Test
    void aZeroWidthNoColourOrInactivePainterRecordsNothing() {
        PaintTrail t = new PaintTrail(painter);
        moveTo(t, 0.0, 1);
        t.apply(activate(0.0, Color.red));
        moveTo(t, 0.1, 1);
        t.apply(activate(0.02));
        moveTo(t, 0.2, 1);
        assertEquals(0, t.getSegments().size());
    }

    @Test
    void aNewPlacementOrNewSettingsStartAnUnconnectedSegment() {
        PaintTrail t = new PaintTrail(painter);
        t.apply(activate(0.02, Color.red));
        moveTo(t, 0.0, 1);
        moveTo(t, 0.1, 1);
        moveTo(t, 0.5, 2);
        t.apply(activate(0.03, Color.red));
        moveTo(t, 0.6, 2);
        assertEquals(3, t.getSegments().size());
        assertEquals(2, t.getSegments().get(0).getCount());
        assertEquals(0.03, t.getSegments().get(2).getWidth());
    }

    @Test
    void aFullSegmentContinuesFromItsLastPoint() {
        PaintTrail t = new PaintTrail(painter);
        t.apply(activate(0.02, Color.blue));
        for (int i = 0; i <= TrailSegment.CAPACITY; i++) {
            moveTo(t, 0.02 * i, 1);
        }
        assertEquals(2, t.getSegments().size());
        TrailSegment second = t.getSegments().get(1);
        assertEquals(2, second.getCount(), "the last point of the full segment, then the new one");
        assertEquals(t.getSegments().get(0).getX(TrailSegment.CAPACITY - 1), second.getX(0));
    }

    @Test
    void erasureClearsTheTrailButTheActivePainterGoesOnPainting() {
        PaintTrail t = new PaintTrail(painter);
        t.apply(activate(0.02, Color.red));
        moveTo(t, 0.0, 1);
        t.apply(new RsPainterChangeRequest(painter.getID(), true, false, false, 0, 0, 0, null));
        assertEquals(0, t.getSegments().size());
        moveTo(t, 0.5, 1);
        assertEquals(1, t.getSegments().size());
    }
}
