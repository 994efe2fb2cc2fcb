package rp1.rossum;

import java.io.Serializable;

/**
 * A closed polygon stored as its edges: {@code segment[i]} runs from vertex i to vertex i+1, and the
 * last edge closes back to vertex 0. Walls, obstacles and floor paint are polygons; containment tests
 * answer "is the paint sensor over this paint" and "would the robot overlap this wall".
 */
public class RsPolygon implements Serializable {
    private static final long serialVersionUID = 1L;

    /** Result of {@link #checkContainment}: the point is strictly inside. */
    public static final int INSIDE = 1;
    /** Result of {@link #checkContainment}: the point is on the boundary (within the tolerance). */
    public static final int ON_BOUNDARY = 0;
    /** Result of {@link #checkContainment}: the point is outside. */
    public static final int OUTSIDE = -1;

    /** The number of edges, equal to the number of vertices. */
    public int nSegment;
    /** The edges, each from one vertex to the next, the last back to the first. */
    public RsSegment[] segment;
    /** Enclosed area in square metres (always positive). */
    public double area;
    /** +1 if the vertices run counter-clockwise, -1 if clockwise. */
    public int orientation;

    /**
     * A copy of {@code p} with the edges {@code segment} (copies of its own): every field as it is,
     * with nothing computed again, so that the copy's numbers are the original's to the bit.
     */
    RsPolygon(RsPolygon p, RsSegment[] segment) {
        this.nSegment = p.nSegment;
        this.segment = segment;
        this.area = p.area;
        this.orientation = p.orientation;
    }

    /**
     * A polygon from its first {@code nSegment} edges, which must join end to start and close.
     *
     * @throws RsPolygonException if there are fewer than three edges or the area is zero
     */
    public RsPolygon(int nSegment, RsSegment[] segment) throws RsPolygonException {
        if (segment == null || nSegment < 3 || nSegment > segment.length) {
            throw new RsPolygonException("a polygon needs at least 3 edges, got " + nSegment);
        }
        this.nSegment = nSegment;
        this.segment = new RsSegment[nSegment];
        for (int i = 0; i < nSegment; i++) {
            this.segment[i] = new RsSegment(segment[i]);
        }
        computeArea();
    }

    /**
     * A polygon through the first {@code nPoint} points of {@code point} (x0, y0, x1, y1, ...), closed
     * automatically; a last point equal to the first is dropped.
     *
     * @throws RsPolygonException if fewer than three distinct vertices remain or the area is zero
     */
    public RsPolygon(double[] point, int nPoint) throws RsPolygonException {
        if (point == null || nPoint < 3 || 2 * nPoint > point.length) {
            throw new RsPolygonException("a polygon needs at least 3 points, got " + nPoint);
        }
        int n = nPoint;
        if (point[0] == point[2 * n - 2] && point[1] == point[2 * n - 1]) {
            n--;
        }
        if (n < 3) {
            throw new RsPolygonException("a polygon needs at least 3 distinct points, got " + n);
        }
        nSegment = n;
        segment = new RsSegment[n];
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            segment[i] = new RsSegment(point[2 * i], point[2 * i + 1], point[2 * j], point[2 * j + 1]);
        }
        computeArea();
    }

    private void computeArea() throws RsPolygonException {
        double twice = 0.0;
        for (int i = 0; i < nSegment; i++) {
            RsSegment s = segment[i];
            twice += s.x * s.getY1() - s.getX1() * s.y;
        }
        if (twice == 0.0 || Double.isNaN(twice)) {
            throw new RsPolygonException("polygon has no area");
        }
        orientation = twice > 0 ? 1 : -1;
        area = Math.abs(twice) / 2.0;
    }

    /**
     * Whether (x, y) is inside the polygon, exactly.
     *
     * @return {@link #INSIDE}, {@link #ON_BOUNDARY} or {@link #OUTSIDE}
     */
    public int checkContainment(double x, double y) {
        return checkContainment(x, y, 0.0);
    }

    /**
     * Whether (x, y) is inside the polygon; points within {@code tolerance} metres of an edge count
     * as on the boundary.
     *
     * @return {@link #INSIDE}, {@link #ON_BOUNDARY} or {@link #OUTSIDE}
     */
    public int checkContainment(double x, double y, double tolerance) {
        return containment(segment, nSegment, x, y, tolerance);
    }

    /**
     * Where (x, y) lies relative to the closed outline made of the first {@code n} edges: within
     * {@code tolerance} of an edge is {@link #ON_BOUNDARY}; otherwise an even-odd crossing count
     * decides. Also answers for degenerate outlines (body parts need not have an area).
     */
    static int containment(RsSegment[] edges, int n, double x, double y, double tolerance) {
        boolean inside = false;
        double tol2 = tolerance * tolerance;
        for (int i = 0; i < n; i++) {
            RsSegment s = edges[i];
            if (distanceSquaredToSegment(s, x, y) <= tol2) {
                return ON_BOUNDARY;
            }
            // The end point is taken from the next edge, not computed as start + v: a vertex must have
            // exactly the same coordinates as the end of one edge and the start of the next, or a ray
            // through it can be counted twice or not at all.
            RsSegment next = edges[(i + 1) % n];
            double y0 = s.y;
            double y1 = next.y;
            if ((y0 > y) != (y1 > y)) {
                double xCross = s.x + (y - y0) / (y1 - y0) * (next.x - s.x);
                if (x < xCross) {
                    inside = !inside;
                }
            }
        }
        return inside ? INSIDE : OUTSIDE;
    }

    /** Squared distance from (x, y) to the closest point of segment {@code s}. */
    static double distanceSquaredToSegment(RsSegment s, double x, double y) {
        double dx = x - s.x;
        double dy = y - s.y;
        double len2 = s.v.x * s.v.x + s.v.y * s.v.y;
        double t = len2 > 0.0 ? (dx * s.v.x + dy * s.v.y) / len2 : 0.0;
        t = Math.max(0.0, Math.min(1.0, t));
        double ex = dx - t * s.v.x;
        double ey = dy - t * s.v.y;
        return ex * ex + ey * ey;
    }

    /** The bounding box of the vertices. */
    public RsRectangle getBounds() {
        RsRectangle r = new RsRectangle();
        for (int i = 0; i < nSegment; i++) {
            r.insert(segment[i].x, segment[i].y);
        }
        return r;
    }
}
