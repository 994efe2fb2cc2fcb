package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** How a part's outline is built from its points (protocol.md section 8.3). */
class BodyOutlineTest {
    @Test
    void aSquareGetsFourEdgesIncludingTheClosingOne() {
        RsSegment[] e = new RsBodyShape(TestPlans.rect(0, 0, 1, 1), 4).getSegmentArray();
        assertEquals(4, e.length);
        assertEquals(0.0, e[3].x);
        assertEquals(1.0, e[3].y);
        assertEquals(0.0, e[3].getX1());
        assertEquals(0.0, e[3].getY1());
    }

    @Test
    void edgesShorterThanOneMillimetreAreDropped() {
        double[] p = {0, 0, 1, 0, 1.0005, 0.0005, 1, 1, 0, 1};
        RsBodyShape s = new RsBodyShape(p, 5);
        assertEquals(4, s.getOutlineEdgeCount());
        assertArrayEquals(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, s.getOutlineVertices());
    }

    @Test
    void aLastPointOnTheFirstClosesTheOutlineWithoutAnExtraEdge() {
        double[] p = {0, 0, 1, 0, 1, 1, 0.0005, 0.0};
        RsBodyShape s = new RsBodyShape(p, 4);
        assertEquals(3, s.getOutlineEdgeCount());
    }

    @Test
    void nPointLimitsThePointsUsed() {
        double[] p = {0, 0, 1, 0, 1, 1, 5, 5, 6, 6};
        assertEquals(3, new RsBodyShape(p, 3).getOutlineEdgeCount());
    }

    @Test
    void transmittedVerticesRebuildTheSameOutline() {
        double[] p = {0, 0, 2, 0, 2, 0.0001, 2, 1, 0, 1, 0, 0};
        RsBodyShape s = new RsBodyShape(p, 6);
        double[] v = s.getOutlineVertices();
        RsBodyShape again = new RsBodyShape(v, v.length / 2);
        assertArrayEquals(v, again.getOutlineVertices());
    }

    @Test
    void aCircleIsA36GonStartingAtAngleZero() {
        RsBodyCircle c = new RsBodyCircle(1.0, 2.0, 0.5);
        RsSegment[] e = c.getSegmentArray();
        assertEquals(36, e.length);
        assertEquals(1.5, e[0].x, 1e-12);
        assertEquals(2.0, e[0].y, 1e-12);
        assertEquals(1.0 + 0.5 * Math.cos(Math.toRadians(10)), e[1].x, 1e-12);
    }

    @Test
    void onePointOrNoPointsMakeNoEdges() {
        assertEquals(0, new RsBodyShape(new double[] {1, 1}, 1).getOutlineEdgeCount());
        assertEquals(0, new RsBodyShape(new double[0], 0).getOutlineEdgeCount());
        assertEquals(0, new RsBodyShape().getOutlineEdgeCount());
    }

    @Test
    void tooFewValuesForNPointIsRefusedNamingTheArgument() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new RsBodyShape(new double[] {0, 0, 1, 1}, 3));
        assertEquals(true, e.getMessage().contains("nPoint"));
    }

    @Test
    void boundsCoverTheOutline() {
        RsRectangle r = new RsBodyShape(TestPlans.rect(-0.1, -0.2, 0.3, 0.4), 4).getRefBounds();
        assertEquals(-0.1, r.x, 1e-12);
        assertEquals(-0.2, r.y, 1e-12);
        assertEquals(0.4, r.width, 1e-12);
        assertEquals(0.6, r.height, 1e-12);
    }
}
