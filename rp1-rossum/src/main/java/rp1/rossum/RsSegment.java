package rp1.rossum;

import java.io.Serializable;

/**
 * A directed line segment: the inherited point is its start, {@link #v} the vector from the start to
 * the end, and {@link #m} the segment's length. Polygons of walls and body parts are lists of these.
 */
public class RsSegment extends RsPoint implements Serializable {
    private static final long serialVersionUID = 1L;

    /** From the start point to the end point. */
    public RsVector v;
    /** Length of the segment (magnitude of {@link #v}). */
    public double m;

    /** A zero-length segment at the origin. */
    public RsSegment() {
        v = new RsVector();
    }

    /**
     * The segment from {@code p0} to {@code p1}.
     *
     * @param p0 the start
     * @param p1 the end
     */
    public RsSegment(RsPoint p0, RsPoint p1) {
        this(p0.x, p0.y, p1.x, p1.y);
    }

    /**
     * The segment from (x0, y0) to (x1, y1).
     *
     * @param x0 the start's x
     * @param y0 the start's y
     * @param x1 the end's x
     * @param y1 the end's y
     */
    public RsSegment(double x0, double y0, double x1, double y1) {
        super(x0, y0);
        v = new RsVector(x1 - x0, y1 - y0);
        m = v.magnitude();
    }

    /** A copy of {@code s}. */
    public RsSegment(RsSegment s) {
        this(s.x, s.y, s.x + s.v.x, s.y + s.v.y);
    }

    /** The x coordinate of the end point. */
    public double getX1() {
        return x + v.x;
    }

    /** The y coordinate of the end point. */
    public double getY1() {
        return y + v.y;
    }

    /** Sets both end points. */
    public void set(double x0, double y0, double x1, double y1) {
        x = x0;
        y = y0;
        v.x = x1 - x0;
        v.y = y1 - y0;
        m = v.magnitude();
    }

    @Override
    public String toString() {
        return "RsSegment[(" + x + ", " + y + ") -> (" + getX1() + ", " + getY1() + ")]";
    }
}
