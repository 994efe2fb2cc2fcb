package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsPoint;
import rp1.rossum.RsRectangle;

/** The plan fitted into the canvas (behavior.md section 10) and mapped back for the mouse. */
class ViewTransformTest {
    /** The WhiteRoom's bounds (behavior.md section 1.8). */
    private static final RsRectangle WHITE_ROOM = new RsRectangle(-0.025, -0.025, 3.05, 3.05);

    @Test
    void aSquarePlanInTheInitialWindowIsFittedToTheHeightLess15PixelsAndCentred() {
        ViewTransform v = ViewTransform.fit(WHITE_ROOM, 500, 400);
        assertEquals(385.0 / 3.05, v.getScale(), 1e-12);
        assertEquals(57.0, v.pixelX(-0.025), 1e-9, "left edge: floor((500 - 385) / 2)");
        assertEquals(7.0, v.pixelY(3.025), 1e-9, "top edge: floor((400 - 385) / 2); +y is up");
        assertEquals(392.0, v.pixelY(-0.025), 1e-9);
    }

    @Test
    void aWidePlanInATallCanvasIsFittedToTheWidth() {
        ViewTransform v = ViewTransform.fit(new RsRectangle(0, 0, 10, 4), 300, 600);
        assertEquals(285.0 / 10.0, v.getScale(), 1e-12);
        assertEquals(7.0, v.pixelX(0.0), 1e-9);
        assertEquals(Math.floor((600 - 114) / 2.0), v.pixelY(4.0), 1e-9);
    }

    @Test
    void aCanvasOf30PixelsOrLessKeepsNoMargin() {
        ViewTransform v = ViewTransform.fit(new RsRectangle(0, 0, 1, 1), 30, 30);
        assertEquals(30.0, v.getScale(), 1e-12);
        assertEquals(0.0, v.pixelX(0.0), 1e-9);
    }

    @Test
    void pixelsMapBackToTheWorldPointDrawnThere() {
        ViewTransform v = ViewTransform.fit(WHITE_ROOM, 640, 480).zoomed(1.7);
        RsPoint p = v.worldToPixel().map(1.234, 2.5);
        assertEquals(p.x, v.pixelX(1.234), 1e-9);
        assertEquals(p.y, v.pixelY(2.5), 1e-9);
        assertEquals(1.234, v.worldX(p.x), 1e-12);
        assertEquals(2.5, v.worldY(p.y), 1e-12);
    }

    @Test
    void zoomingKeepsTheFloorPointAtTheCanvasCentreInPlace() {
        ViewTransform v = ViewTransform.fit(WHITE_ROOM, 500, 400);
        ViewTransform z = v.zoomed(PlanCanvas.ZOOM_STEP);
        assertEquals(v.worldX(250), z.worldX(250), 1e-12);
        assertEquals(v.worldY(200), z.worldY(200), 1e-12);
        assertEquals(v.getScale() * PlanCanvas.ZOOM_STEP, z.getScale(), 1e-12);
    }

    @Test
    void emptyCanvasesAndPlansAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> ViewTransform.fit(WHITE_ROOM, 0, 400));
        assertThrows(IllegalArgumentException.class, () -> ViewTransform.fit(new RsRectangle(), 500, 400));
        assertThrows(IllegalArgumentException.class, () -> ViewTransform.fit(WHITE_ROOM, 500, 400).zoomed(0.0));
    }
}
