package rp1.rossum;

import java.io.Serializable;

/**
 * An axis-aligned rectangle (lower-left corner {@code x, y}, {@code width}, {@code height}) used for
 * bounding boxes. A rectangle made with the no-argument constructor is empty ("not populated") until
 * the first point is inserted or another rectangle is united with it.
 */
public class RsRectangle implements Serializable {
    private static final long serialVersionUID = 1L;

    public double x;
    public double y;
    public double width;
    public double height;
    private boolean populated;

    /** An empty rectangle. */
    public RsRectangle() {
    }

    /** A copy of {@code r}. */
    public RsRectangle(RsRectangle r) {
        copy(r);
    }

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

    public void setBounds(double x, double y, double width, double height) {
        this.x = x;
        this.y = y;
        this.width = width;
        this.height = height;
        populated = true;
    }

    public void setSize(double width, double height) {
        this.width = width;
        this.height = height;
    }

    /** Moves the lower-left corner to (x, y), keeping the size. */
    public void move(double x, double y) {
        this.x = x;
        this.y = y;
    }

    public void translate(double dx, double dy) {
        x += dx;
        y += dy;
    }

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
