package rp1.rossum;

import java.io.Serializable;

/**
 * The intersection of two line segments. After {@link #process} the fields hold the result:
 * whether they intersect, the fraction along each segment ({@code t1}, {@code t2}, both in [0, 1],
 * end points included) and the intersection point. Parallel and nearly parallel segments
 * (|determinant| below 1e-9) never intersect; this is the rule the collision model relies on.
 */
public class RsSegSect implements Serializable {
    private static final long serialVersionUID = 1L;

    /** Segments whose direction cross product is smaller than this are treated as parallel. */
    public static final double PARALLEL_LIMIT = 1.0e-9;

    /**
     * Whether the segments intersect (end points included); the other fields are meaningful only
     * then.
     */
    public boolean intersection;
    /** Fraction along the first segment at the intersection. */
    public double t1;
    /** Fraction along the second segment at the intersection. */
    public double t2;
    /** The intersection point. */
    public double x;
    /** The intersection point. */
    public double y;

    /** No intersection yet: call {@code intersect} or its relatives to fill it in. */
    public RsSegSect() {
    }

    /**
     * Intersects {@code s1} with {@code s2}.
     *
     * @return whether they intersect (also stored in {@link #intersection})
     */
    public boolean process(RsSegment s1, RsSegment s2) {
        return process(s1.x, s1.y, s1.v.x, s1.v.y, s2.x, s2.y, s2.v.x, s2.v.y);
    }

    /**
     * Intersects the segment from (ax, ay) along (adx, ady) with the segment from (bx, by) along
     * (bdx, bdy), without allocating segments.
     */
    public boolean process(double ax, double ay, double adx, double ady,
                           double bx, double by, double bdx, double bdy) {
        intersection = false;
        double det = adx * bdy - ady * bdx;
        if (Math.abs(det) < PARALLEL_LIMIT) {
            return false;
        }
        double ex = bx - ax;
        double ey = by - ay;
        double u1 = (ex * bdy - ey * bdx) / det;
        if (u1 < 0.0 || u1 > 1.0) {
            return false;
        }
        double u2 = (ex * ady - ey * adx) / det;
        if (u2 < 0.0 || u2 > 1.0) {
            return false;
        }
        t1 = u1;
        t2 = u2;
        x = ax + u1 * adx;
        y = ay + u1 * ady;
        intersection = true;
        return true;
    }
}
