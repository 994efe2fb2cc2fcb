package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Containment and area of polygons. */
class RsPolygonTest {

    private static RsPolygon circleAt(double cx, double cy) throws RsPolygonException {
        double[] xy = new double[72];
        for (int k = 0; k < 36; k++) {
            xy[2 * k] = cx + 0.15 * Math.cos(k * Math.PI / 18);
            xy[2 * k + 1] = cy + 0.15 * Math.sin(k * Math.PI / 18);
        }
        return new RsPolygon(xy, 36);
    }

    @Test
    void aPointLevelWithAVertexIsCountedConsistently() throws Exception {
        RsPolygon far = circleAt(9.0, 2.0);
        double vertexY = 2.0 + 0.15 * Math.sin(2 * Math.PI / 18);
        assertEquals(RsPolygon.OUTSIDE, far.checkContainment(1.14, vertexY),
                "a point far to the left, level with two vertices of the polygon, is outside");
        assertEquals(RsPolygon.INSIDE, far.checkContainment(9.0, vertexY));
    }

    @Test
    void boundaryAndToleranceAreReported() throws Exception {
        RsPolygon square = new RsPolygon(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, 4);
        assertEquals(1.0, square.area);
        assertEquals(1, square.orientation);
        assertEquals(RsPolygon.ON_BOUNDARY, square.checkContainment(0.5, 0.0));
        assertEquals(RsPolygon.OUTSIDE, square.checkContainment(1.00005, 0.5));
        assertEquals(RsPolygon.ON_BOUNDARY, square.checkContainment(1.00005, 0.5, 1e-4));
        assertEquals(RsPolygon.INSIDE, square.checkContainment(0.5, 0.5));
    }
}
