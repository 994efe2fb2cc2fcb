package rp1.rossum;

import java.io.Serializable;

/**
 * An affine transform of the plane, stored as the upper two rows of a 3x3 matrix:
 * <pre>
 *   | m11 m12 m13 |   x' = m11*x + m12*y + m13
 *   | m21 m22 m23 |   y' = m21*x + m22*y + m23
 * </pre>
 * A robot pose is a rigid transform (rotation by the heading theta, then translation to the body
 * origin) mapping body coordinates to world coordinates; a view transform may add a scale and a flip
 * to map world metres to pixels.
 */
public class RsTransform implements Serializable {
    private static final long serialVersionUID = 1L;

    /** Matrix element m11 (see the class comment). */
    public double m11;
    /** Matrix element m12 (see the class comment). */
    public double m12;
    /** Matrix element m13 (see the class comment). */
    public double m13;
    /** Matrix element m21 (see the class comment). */
    public double m21;
    /** Matrix element m22 (see the class comment). */
    public double m22;
    /** Matrix element m23 (see the class comment). */
    public double m23;

    /** The identity transform. */
    public RsTransform() {
        m11 = 1.0;
        m22 = 1.0;
    }

    /** A copy of {@code t}. */
    public RsTransform(RsTransform t) {
        copy(t);
    }

    /**
     * The rigid transform for a pose: rotation by {@code theta} (radians, counter-clockwise) followed
     * by translation to ({@code x}, {@code y}).
     */
    public RsTransform(double theta, double x, double y) {
        setTheta(theta);
        setOffset(x, y);
    }

    /** The rotation by {@code angle} radians (counter-clockwise) about the point (px, py). */
    public static RsTransform rotationAbout(double angle, double px, double py) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        return new RsTransform(angle, px - (c * px - s * py), py - (s * px + c * py));
    }

    /** The composition {@code a} after {@code b}: maps p to a(b(p)). */
    public RsTransform(RsTransform a, RsTransform b) {
        concat(a, b);
    }

    /** Sets this transform to {@code a} after {@code b} (the matrix product a*b). */
    public void concat(RsTransform a, RsTransform b) {
        double n11 = a.m11 * b.m11 + a.m12 * b.m21;
        double n12 = a.m11 * b.m12 + a.m12 * b.m22;
        double n13 = a.m11 * b.m13 + a.m12 * b.m23 + a.m13;
        double n21 = a.m21 * b.m11 + a.m22 * b.m21;
        double n22 = a.m21 * b.m12 + a.m22 * b.m22;
        double n23 = a.m21 * b.m13 + a.m22 * b.m23 + a.m23;
        m11 = n11;
        m12 = n12;
        m13 = n13;
        m21 = n21;
        m22 = n22;
        m23 = n23;
    }

    /** The rotation angle of this transform, in (-pi, pi]. */
    public double getTheta() {
        return Math.atan2(m21, m11);
    }

    /** Replaces the rotation part with a pure rotation by {@code theta} (any scale is dropped). */
    public void setTheta(double theta) {
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        m11 = c;
        m12 = -s;
        m21 = s;
        m22 = c;
    }

    /** The translation part: where the origin is mapped to. */
    public RsPoint getOffset() {
        return new RsPoint(m13, m23);
    }

    /**
     * Sets the translation part: the origin is mapped to (x, y).
     *
     * @param x the new m13
     * @param y the new m23
     */
    public void setOffset(double x, double y) {
        m13 = x;
        m23 = y;
    }

    /** Maps a direction (rotation and scale only, no translation). */
    public RsVector mapVector(double x, double y) {
        return new RsVector(m11 * x + m12 * y, m21 * x + m22 * y);
    }

    /**
     * The image of {@code p}.
     *
     * @param p the point
     * @return a new point
     */
    public RsPoint map(RsPoint p) {
        return map(p.x, p.y);
    }

    /**
     * The image of (x, y).
     *
     * @param x the x coordinate
     * @param y the y coordinate
     * @return a new point
     */
    public RsPoint map(double x, double y) {
        return new RsPoint(m11 * x + m12 * y + m13, m21 * x + m22 * y + m23);
    }

    /** Maps (x, y) into {@code out} without allocating. */
    public void map(double x, double y, RsPoint out) {
        double nx = m11 * x + m12 * y + m13;
        double ny = m21 * x + m22 * y + m23;
        out.x = nx;
        out.y = ny;
    }

    /** Maps the first {@code n} points and rounds them to integer (pixel) coordinates. */
    public void iMapArray(int n, RsPoint[] p, int[] xOut, int[] yOut) {
        for (int i = 0; i < n; i++) {
            iMapArrayIndex(p[i].x, p[i].y, i, xOut, yOut);
        }
    }

    /** Maps (x, y), rounds it, and stores it at {@code index} of the output arrays. */
    public void iMapArrayIndex(double x, double y, int index, int[] xOut, int[] yOut) {
        xOut[index] = (int) Math.round(m11 * x + m12 * y + m13);
        yOut[index] = (int) Math.round(m21 * x + m22 * y + m23);
    }

    /** Stores the image of segment {@code in} in {@code out}. */
    public void map2(RsSegment in, RsSegment out) {
        double x0 = m11 * in.x + m12 * in.y + m13;
        double y0 = m21 * in.x + m22 * in.y + m23;
        double vx = m11 * in.v.x + m12 * in.v.y;
        double vy = m21 * in.v.x + m22 * in.v.y;
        out.x = x0;
        out.y = y0;
        out.v.x = vx;
        out.v.y = vy;
        out.m = Math.sqrt(vx * vx + vy * vy);
    }

    /** Stores the image of point {@code in} in {@code out}. */
    public void map2(RsPoint in, RsPoint out) {
        map(in.x, in.y, out);
    }

    /**
     * Makes this transform equal to {@code t}.
     *
     * @param t the transform to copy
     */
    public void copy(RsTransform t) {
        m11 = t.m11;
        m12 = t.m12;
        m13 = t.m13;
        m21 = t.m21;
        m22 = t.m22;
        m23 = t.m23;
    }

    /**
     * Whether {@code t} is this transform to the bit (null is not): what was worked out for one pose
     * can be kept for a pose asked about again only if they are the same number for number.
     *
     * @param t the transform to compare, or null
     * @return whether all six elements have the same bits
     */
    public boolean sameBits(RsTransform t) {
        return t != null && sameBits(m11, t.m11) && sameBits(m12, t.m12) && sameBits(m13, t.m13)
                && sameBits(m21, t.m21) && sameBits(m22, t.m22) && sameBits(m23, t.m23);
    }

    /** Whether two numbers are the same to the bit. */
    static boolean sameBits(double a, double b) {
        return Double.doubleToRawLongBits(a) == Double.doubleToRawLongBits(b);
    }

    /** The length a unit vector has after mapping (1 for rigid transforms, pixels per metre for a view). */
    public double getScale() {
        return Math.sqrt(m11 * m11 + m21 * m21);
    }

    @Override
    public String toString() {
        return "RsTransform[theta=" + getTheta() + ", offset=(" + m13 + ", " + m23 + "), scale=" + getScale() + "]";
    }
}
