package rp1.rossum;

/**
 * Outline geometry of body parts: building the closed edge list from the points a client gives
 * (protocol.md section 8.3), the 36-edge circle, mapping to world coordinates, and the "inside or
 * near" test of the placement clear test.
 */
final class BodyOutline {
    /** Edges shorter than 1 mm (squared length below this) are dropped. */
    static final double MIN_EDGE_SQUARED = 1.0e-6;
    /** A circle part is modelled as a polygon with this many edges. */
    static final int CIRCLE_EDGES = 36;

    private BodyOutline() {
    }

    /**
     * The closed outline through the first {@code nPoint} points (x0, y0, x1, y1, ...): an edge from
     * each kept point to the next one at least 1 mm away, then a closing edge back to the first point
     * unless the last kept point already lies within 1 mm of it.
     *
     * @throws IllegalArgumentException if nPoint is negative or the array holds fewer points
     */
    static RsSegment[] edgesFromPoints(double[] point, int nPoint) {
        if (nPoint < 0) {
            throw new IllegalArgumentException("nPoint is negative: " + nPoint);
        }
        if (nPoint > 0 && (point == null || point.length < 2 * nPoint)) {
            throw new IllegalArgumentException("point holds fewer than nPoint=" + nPoint + " points: "
                    + (point == null ? "null" : point.length + " values"));
        }
        if (nPoint == 0) {
            return new RsSegment[0];
        }
        double firstX = point[0];
        double firstY = point[1];
        double px = firstX;
        double py = firstY;
        RsSegment[] edges = new RsSegment[nPoint];
        int n = 0;
        for (int i = 1; i < nPoint; i++) {
            double x = point[2 * i];
            double y = point[2 * i + 1];
            if (squaredDistance(px, py, x, y) < MIN_EDGE_SQUARED) {
                continue;
            }
            edges[n++] = new RsSegment(px, py, x, y);
            px = x;
            py = y;
        }
        if (squaredDistance(px, py, firstX, firstY) >= MIN_EDGE_SQUARED) {
            edges[n++] = new RsSegment(px, py, firstX, firstY);
        }
        RsSegment[] result = new RsSegment[n];
        System.arraycopy(edges, 0, result, 0, n);
        return result;
    }

    /** The points of the 36-gon inscribed in the circle, first vertex at angle 0. */
    static double[] circlePoints(double xCenter, double yCenter, double radius) {
        double[] p = new double[2 * CIRCLE_EDGES];
        for (int i = 0; i < CIRCLE_EDGES; i++) {
            double a = 2.0 * Math.PI * i / CIRCLE_EDGES;
            p[2 * i] = xCenter + radius * Math.cos(a);
            p[2 * i + 1] = yCenter + radius * Math.sin(a);
        }
        return p;
    }

    /** The points of an axis-aligned rectangle centred on (x, y), counter-clockwise. */
    static double[] rectanglePoints(double x, double y, double length, double width) {
        double hx = length / 2.0;
        double hy = width / 2.0;
        return new double[] {x - hx, y - hy, x + hx, y - hy, x + hx, y + hy, x - hx, y + hy};
    }

    private static double squaredDistance(double x0, double y0, double x1, double y1) {
        double dx = x1 - x0;
        double dy = y1 - y0;
        return dx * dx + dy * dy;
    }

    /** Copies of the edges mapped by {@code t}. */
    static RsSegment[] map(RsSegment[] edges, RsTransform t) {
        RsSegment[] out = new RsSegment[edges.length];
        for (int i = 0; i < edges.length; i++) {
            out[i] = new RsSegment();
            t.map2(edges[i], out[i]);
        }
        return out;
    }

    /**
     * The edges mapped by {@code t}, written into {@code into} if it has room for exactly as many
     * (else into new segments): for searches that keep one outline to fill again and again.
     */
    static RsSegment[] mapInto(RsSegment[] edges, RsTransform t, RsSegment[] into) {
        if (into == null || into.length != edges.length) {
            return map(edges, t);
        }
        for (int i = 0; i < edges.length; i++) {
            t.map2(edges[i], into[i]);
        }
        return into;
    }

    /** Independent copies of the edges. */
    static RsSegment[] copy(RsSegment[] edges) {
        RsSegment[] out = new RsSegment[edges.length];
        for (int i = 0; i < edges.length; i++) {
            out[i] = new RsSegment(edges[i]);
        }
        return out;
    }

    /** The bounding box of the edges' start points (which are all the vertices of a closed outline). */
    static RsRectangle bounds(RsSegment[] edges) {
        RsRectangle r = new RsRectangle();
        for (RsSegment s : edges) {
            r.insert(s.x, s.y);
        }
        return r;
    }

    /**
     * Whether (x, y) lies inside the closed outline or within {@code tolerance} of one of its edges.
     * Works for degenerate outlines too (fewer than three edges, no area), where only the distance
     * counts.
     */
    static boolean insideOrNear(RsSegment[] edges, double x, double y, double tolerance) {
        return RsPolygon.containment(edges, edges.length, x, y, tolerance) != RsPolygon.OUTSIDE;
    }
}
