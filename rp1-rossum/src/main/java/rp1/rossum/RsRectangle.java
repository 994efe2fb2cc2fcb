package rp1.rossum;

import java.io.Serializable;

/**
 * An axis-aligned rectangle (lower-left corner {@code x, y}, {@code width}, {@code height}) used for
 * bounding boxes. A rectangle made with the no-argument constructor is empty ("not populated") until
 * the first point is inserted or another rectangle is united with it.
 */
public class RsRectangle implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The lower-left corner's x. */
    public double x;
    /** The lower-left corner's y. */
    public double y;
    /** The extent along x (0 or more). */
    public double width;
    /** The extent along y (0 or more). */
    public double height;
    private boolean populated;

    /** An empty rectangle. */
    public RsRectangle() {
    }

    /** A copy of {@code r}. */
    public RsRectangle(RsRectangle r) {
        copy(r);
    }

    /**
     * The rectangle with lower-left corner (x, y) and this size.
     *
     * @param x the corner's x
     * @param y the corner's y
     * @param width the extent along x
     * @param height the extent along y
     */
    public RsRectangle(double x, double y, double width, double height) {
        setBounds(x, y, width, height);
    }

    /** The bounding box of the first {@code n} points (empty if n is 0). */
    public RsRectangle(RsPoint[] p, int n) {
        for (int i = 0; i < n; i++) {
            insert(p[i]);
        }
    }

    /** Grows the rectangle to include {@code p}. */
    public void insert(RsPoint p) {
        insert(p.x, p.y);
    }

    /** Grows the rectangle to include (px, py). */
    public void insert(double px, double py) {
        if (!populated) {
            setBounds(px, py, 0.0, 0.0);
            return;
        }
        double x1 = Math.max(x + width, px);
        double y1 = Math.max(y + height, py);
        x = Math.min(x, px);
        y = Math.min(y, py);
        width = x1 - x;
        height = y1 - y;
    }

    /**
     * Sets corner and size; the rectangle is then no longer empty.
     *
     * @param x the corner's x
     * @param y the corner's y
     * @param width the extent along x
     * @param height the extent along y
     */
    public void setBounds(double x, double y, double width, double height) {
        this.x = x;
        this.y = y;
        this.width = width;
        this.height = height;
        populated = true;
    }

    /**
     * Sets the size, keeping the corner. An empty rectangle stays empty.
     *
     * @param width the extent along x
     * @param height the extent along y
     */
    public void setSize(double width, double height) {
        this.width = width;
        this.height = height;
    }

    /** Moves the lower-left corner to (x, y), keeping the size. */
    public void move(double x, double y) {
        this.x = x;
        this.y = y;
    }

    /**
     * Moves the rectangle by (dx, dy).
     *
     * @param dx offset along x
     * @param dy offset along y
     */
    public void translate(double dx, double dy) {
        x += dx;
        y += dy;
    }

    /**
     * Moves the rectangle by {@code v}.
     *
     * @param v the offset
     */
    public void translate(RsVector v) {
        translate(v.x, v.y);
    }

    /** Grows this rectangle to cover {@code r} as well; an empty {@code r} changes nothing. */
    public void union(RsRectangle r) {
        if (r == null || !r.populated) {
            return;
        }
        insert(r.x, r.y);
        insert(r.x + r.width, r.y + r.height);
    }

    /**
     * Makes this rectangle equal to {@code r}, emptiness included.
     *
     * @param r the rectangle to copy
     */
    public void copy(RsRectangle r) {
        x = r.x;
        y = r.y;
        width = r.width;
        height = r.height;
        populated = r.populated;
    }

    /** Shrinks this rectangle to its intersection with the given one (empty if they do not overlap). */
    public void clip(double cx, double cy, double cWidth, double cHeight) {
        if (!populated) {
            return;
        }
        double x0 = Math.max(x, cx);
        double y0 = Math.max(y, cy);
        double x1 = Math.min(x + width, cx + cWidth);
        double y1 = Math.min(y + height, cy + cHeight);
        if (x1 < x0 || y1 < y0) {
            populated = false;
            x = y = width = height = 0.0;
            return;
        }
        setBounds(x0, y0, x1 - x0, y1 - y0);
    }

    /**
     * Whether {@code p} lies inside or on the edge.
     *
     * @param p the point
     * @return false for an empty rectangle
     */
    public boolean contains(RsPoint p) {
        return contains(p.x, p.y);
    }

    /** Whether (px, py) lies inside or on the edge. */
    public boolean contains(double px, double py) {
        return populated && px >= x && px <= x + width && py >= y && py <= y + height;
    }

    /** Whether the two rectangles overlap (touching edges count). */
    public boolean intersects(RsRectangle r) {
        return populated && r.populated
                && r.x <= x + width && x <= r.x + r.width
                && r.y <= y + height && y <= r.y + r.height;
    }

    /** Replaces this rectangle by the bounding box of its image under {@code t}. */
    public void transform(RsTransform t) {
        if (!populated) {
            return;
        }
        RsPoint a = t.map(x, y);
        RsPoint b = t.map(x + width, y);
        RsPoint c = t.map(x + width, y + height);
        RsPoint d = t.map(x, y + height);
        populated = false;
        insert(a);
        insert(b);
        insert(c);
        insert(d);
    }

    /** Whether the rectangle holds any area or point (false for a new, empty rectangle). */
    public boolean isPopulated() {
        return populated;
    }

    @Override
    public String toString() {
        return populated ? "RsRectangle[" + x + ", " + y + ", " + width + " x " + height + "]" : "RsRectangle[empty]";
    }
}
