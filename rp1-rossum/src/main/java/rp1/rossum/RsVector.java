package rp1.rossum;

import java.io.Serializable;

/**
 * A two-dimensional vector (direction and magnitude) in metres, used for displacements, directions of
 * travel and sight lines.
 *
 * <p>Naming convention: the one-argument forms ({@code unit()}, {@code normal()}, {@code add(v)},
 * {@code subtract(v)}, {@code scale(s)}) return a new vector and leave this one unchanged; the
 * two-argument forms ({@code add(a, b)}, {@code scale(s, v)}, ...) store their result in this vector
 * and return {@code this}.
 */
public class RsVector implements Serializable {
    private static final long serialVersionUID = 1L;

    /** Magnitudes below this are treated as zero when a direction is needed. */
    public static final double NEARLY_ZERO = 1.0E-9d;

    /** The x component. */
    public double x;
    /** The y component. */
    public double y;

    /** The zero vector. */
    public RsVector() {
    }

    /** A copy of {@code v}. */
    public RsVector(RsVector v) {
        this(v.x, v.y);
    }

    /**
     * The vector (x, y).
     *
     * @param x the x component
     * @param y the y component
     */
    public RsVector(double x, double y) {
        this.x = x;
        this.y = y;
    }

    /**
     * A new unit vector with this vector's direction.
     *
     * @throws ArithmeticException if this vector's magnitude is below {@link #NEARLY_ZERO}
     */
    public RsVector unit() throws ArithmeticException {
        return new RsVector().unit(this);
    }

    /**
     * Sets this vector to the unit vector in the direction of {@code v}.
     *
     * @return this vector
     * @throws ArithmeticException if {@code v} has (nearly) zero magnitude
     */
    public RsVector unit(RsVector v) throws ArithmeticException {
        double m = v.magnitude();
        if (m < NEARLY_ZERO) {
            throw new ArithmeticException("cannot take the direction of a zero-length vector");
        }
        double vx = v.x;
        double vy = v.y;
        x = vx / m;
        y = vy / m;
        return this;
    }

    /** A new vector perpendicular to this one, rotated 90 degrees counter-clockwise. */
    public RsVector normal() {
        return new RsVector(-y, x);
    }

    /** Sets this vector to {@code v} rotated 90 degrees counter-clockwise; returns this vector. */
    public RsVector normal(RsVector v) {
        double vx = v.x;
        x = -v.y;
        y = vx;
        return this;
    }

    /**
     * The length.
     *
     * @return the Euclidean norm
     */
    public double magnitude() {
        return Math.sqrt(x * x + y * y);
    }

    /**
     * The dot product with {@code v}.
     *
     * @param v the other vector
     * @return x·v.x + y·v.y
     */
    public double dot(RsVector v) {
        return x * v.x + y * v.y;
    }

    /**
     * The signed angle (radians, counter-clockwise positive, in [-pi, pi]) needed to turn from the
     * direction of {@code a} to the direction of {@code b}.
     *
     * @throws ArithmeticException if either vector has (nearly) zero magnitude
     */
    public static double turn(RsVector a, RsVector b) throws ArithmeticException {
        return unitTurn(a.unit(), b.unit());
    }

    /** As {@link #turn}, for vectors already known to be of unit length (no check is made). */
    public static double unitTurn(RsVector a, RsVector b) {
        return Math.atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    }

    /** A new vector, this plus {@code v}. */
    public RsVector add(RsVector v) {
        return new RsVector(x + v.x, y + v.y);
    }

    /** Sets this vector to {@code a + b}; returns this vector. */
    public RsVector add(RsVector a, RsVector b) {
        double sx = a.x + b.x;
        double sy = a.y + b.y;
        x = sx;
        y = sy;
        return this;
    }

    /** A new vector, this minus {@code v}. */
    public RsVector subtract(RsVector v) {
        return new RsVector(x - v.x, y - v.y);
    }

    /** Sets this vector to {@code a - b}; returns this vector. */
    public RsVector subtract(RsVector a, RsVector b) {
        double dx = a.x - b.x;
        double dy = a.y - b.y;
        x = dx;
        y = dy;
        return this;
    }

    /** A new vector, this one multiplied by {@code s}. */
    public RsVector scale(double s) {
        return new RsVector(x * s, y * s);
    }

    /** Sets this vector to {@code s * v}; returns this vector. */
    public RsVector scale(double s, RsVector v) {
        x = s * v.x;
        y = s * v.y;
        return this;
    }

    @Override
    public String toString() {
        return "RsVector(" + x + ", " + y + ")";
    }
}
