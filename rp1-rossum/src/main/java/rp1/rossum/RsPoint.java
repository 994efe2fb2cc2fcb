package rp1.rossum;

import java.io.Serializable;

/**
 * A mutable point in the plane (metres in world or body coordinates, or pixels when produced by a
 * screen transform). {@code move} sets the coordinates, {@code translate} offsets them.
 */
public class RsPoint implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The x coordinate. */
    public double x;
    /** The y coordinate. */
    public double y;

    /** The origin. */
    public RsPoint() {
    }

    /** A copy of {@code p}. */
    public RsPoint(RsPoint p) {
        this(p.x, p.y);
    }

    /**
     * The point (x, y).
     *
     * @param x the x coordinate
     * @param y the y coordinate
     */
    public RsPoint(double x, double y) {
        this.x = x;
        this.y = y;
    }

    /**
     * The point (x, y), from pixel coordinates.
     *
     * @param x the x coordinate
     * @param y the y coordinate
     */
    public RsPoint(int x, int y) {
        this((double) x, (double) y);
    }

    /** The point at the tip of {@code v} placed at the origin. */
    public RsPoint(RsVector v) {
        this(v.x, v.y);
    }

    /** The vector from {@code p} to this point ({@code this - p}). */
    public RsVector subtract(RsPoint p) {
        return new RsVector(x - p.x, y - p.y);
    }

    /** Sets the coordinates. */
    public void move(double x, double y) {
        this.x = x;
        this.y = y;
    }

    /** Sets the coordinates. */
    public void move(int x, int y) {
        move((double) x, (double) y);
    }

    /** Offsets the coordinates by {@code (dx, dy)}. */
    public void translate(double dx, double dy) {
        x += dx;
        y += dy;
    }

    /** Offsets the coordinates by {@code (dx, dy)}. */
    public void translate(int dx, int dy) {
        translate((double) dx, (double) dy);
    }

    /** Offsets the coordinates by {@code v}. */
    public void translate(RsVector v) {
        translate(v.x, v.y);
    }

    /**
     * The distance to {@code p}.
     *
     * @param p the other point
     * @return the Euclidean distance
     */
    public double distance(RsPoint p) {
        double dx = x - p.x;
        double dy = y - p.y;
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** Copies the coordinates of {@code p} into this point. */
    public void copy(RsPoint p) {
        x = p.x;
        y = p.y;
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ")";
    }
}
