package rp1.rossum;

import java.awt.Graphics;
import rp1.rossum.event.RsEncoderStatusEvent;

/**
 * A wheel of a wheel system: drawn (turned by its steering angle) and, optionally, carrying a rotary
 * encoder. Wheels never collide. The hub (x, y) is in body coordinates; the outline is drawn rotated
 * about it. The encoder id is the wheel's part id.
 *
 * <p>Encoder model (behavior.md section 5.8): at every motion evaluation the wheel angle advances by
 * the distance its hub travelled since the previous evaluation divided by the wheel radius, using the
 * hub speed remembered from that evaluation; the accumulator counts interval boundaries crossed
 * (signed), the absolute accumulator counts them unsigned.
 */
public class RsWheel extends RsBodyShape implements RsEncoder {
    private static final long serialVersionUID = 1L;
    private static final double TWO_PI = 2.0 * Math.PI;

    /** Steering (or caster) angle relative to the body's x axis, radians; used for drawing. */
    protected double motionOrientationOffset;
    /** Number of encoder intervals per turn; 0 for a wheel without encoder. */
    protected int encoderIntervalCount;
    /** Width of one encoder interval, radians. */
    protected double encoderIntervalWidth;
    /** Signed count of interval boundaries crossed (backwards counts down). */
    protected int encoderAccumulator;
    /** Unsigned count of interval boundaries crossed. */
    protected int encoderAbsoluteAccumulator;
    /** +1 if the last movement was forward, -1 if backward, 0 if the wheel never moved. */
    protected int encoderQuadrature;
    /** Wheel angle in [0, 2 pi). */
    protected double encoderAngle;
    /** The interval the wheel angle is in. */
    protected int encoderInterval;
    /** Hub speed remembered from the previous evaluation, m/s (signed). */
    protected double encoderMotionVelocity;
    /** Simulation time of the previous evaluation, seconds. */
    protected double encoderMotionTime;

    private final double hubX;
    private final double hubY;
    private final double wheelRadius;
    private final double maxAbsSteeringAngle;

    /**
     * A wheel that does not steer.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param x hub position, body coordinates
     * @param y hub position, body coordinates
     * @param radius wheel radius, metres
     */
    public RsWheel(double[] point, int nPoint, double x, double y, double radius) {
        this(point, nPoint, x, y, radius, 0.0);
    }

    /**
     * A wheel that may steer up to {@code maxAbsSteeringAngle} radians either way.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param x hub position, body coordinates
     * @param y hub position, body coordinates
     * @param radius wheel radius, metres
     * @param maxAbsSteeringAngle steering limit, radians (0 = fixed)
     */
    public RsWheel(double[] point, int nPoint, double x, double y, double radius, double maxAbsSteeringAngle) {
        super(point, nPoint);
        hubX = x;
        hubY = y;
        wheelRadius = radius;
        this.maxAbsSteeringAngle = maxAbsSteeringAngle;
        refBounds = computeRefBounds();
    }

    /** Whether the wheel turns: it has a steering limit above 0. */
    public boolean isWheelSteerable() {
        return maxAbsSteeringAngle > 0.0;
    }

    /** Wheel radius in metres (0 for a caster). */
    public double getWheelRadius() {
        return wheelRadius;
    }

    /** Steering limit either way, radians (0 = fixed wheel). */
    public double getMaxAbsSteeringAngle() {
        return maxAbsSteeringAngle;
    }

    /** Hub position, body coordinates. */
    public double getX() {
        return hubX;
    }

    /** Hub position, body coordinates. */
    public double getY() {
        return hubY;
    }

    /** The current steering (or caster) angle relative to the body, radians. */
    public double getSteeringAngle() {
        return motionOrientationOffset;
    }

    /** The number of encoder intervals per revolution (0 = no encoder). */
    public int getEncoderIntervalCount() {
        return encoderIntervalCount;
    }

    /** The outline's bounding box (body coordinates), before any steering. */
    protected RsRectangle computeRefBounds() {
        return BodyOutline.bounds(outline());
    }

    /**
     * Fits an encoder with {@code nIntervals} intervals per revolution (its state starts at zero).
     *
     * @return this wheel as the encoder, or null when nIntervals is not positive
     */
    public RsEncoder addEncoder(int nIntervals) {
        if (nIntervals <= 0) {
            return null;
        }
        encoderIntervalCount = nIntervals;
        encoderIntervalWidth = TWO_PI / nIntervals;
        resetEncoder();
        return this;
    }

    /** Zeroes the encoder state: accumulators, quadrature, angle, interval and remembered speed. */
    public void resetEncoder() {
        encoderAccumulator = 0;
        encoderAbsoluteAccumulator = 0;
        encoderQuadrature = 0;
        encoderAngle = 0.0;
        encoderInterval = 0;
        encoderMotionVelocity = 0.0;
        encoderMotionTime = 0.0;
    }

    /** The interval number of a wheel angle: round(angle / intervalWidth). */
    protected int getEncoderBin(double angle) {
        return (int) Math.floor(angle / encoderIntervalWidth + 0.5);
    }

    /**
     * Advances the encoder to the motion's current time using the hub speed remembered from the
     * previous evaluation, then remembers the hub speed under {@code motion} (0 if it has ended).
     */
    protected void applyMotion(RsMotion motion) {
        if (encoderIntervalCount <= 0 || wheelRadius <= 0.0) {
            return;
        }
        double t = motion.time;
        if (encoderMotionVelocity != 0.0) {
            double angle = encoderAngle + (t - encoderMotionTime) * encoderMotionVelocity / wheelRadius;
            int bin = getEncoderBin(angle);
            encoderAccumulator += bin - encoderInterval;
            encoderAbsoluteAccumulator += Math.abs(bin - encoderInterval);
            encoderQuadrature = encoderMotionVelocity < 0.0 ? -1 : 1;
            encoderAngle = wrapAngle(angle);
            encoderInterval = getEncoderBin(encoderAngle);
        }
        encoderMotionVelocity = motion.getMotionDepictionAtBodyPoint(hubX, hubY).getSignedSpeed();
        encoderMotionTime = t;
    }

    /** Into [0, 2 pi) for non-negative angles; a negative angle a maps to 2 pi - (-a mod 2 pi), as in RP1 0.60. */
    private static double wrapAngle(double angle) {
        if (angle >= 0.0) {
            return angle % TWO_PI;
        }
        return TWO_PI - (-angle % TWO_PI);
    }

    /** {@code t} followed by a rotation of {@code angle} radians about the point (x, y). */
    protected RsTransform rotateAboutPivot(RsTransform t, double x, double y, double angle) {
        return new RsTransform(t, RsTransform.rotationAbout(angle, x, y));
    }

    /** Sets the steering (or caster) angle used for drawing, radians relative to the body. */
    protected void setOrientation(double angle) {
        motionOrientationOffset = angle;
    }

    /** A placement straightens the wheel; the encoder keeps its counts. */
    @Override
    public void resetStateData() {
        motionOrientationOffset = 0.0;
    }

    @Override
    public void copyStateData(RsBodyPart source) {
        super.copyStateData(source);
        if (source instanceof RsWheel) {
            RsWheel w = (RsWheel) source;
            motionOrientationOffset = w.motionOrientationOffset;
            encoderIntervalCount = w.encoderIntervalCount;
            encoderIntervalWidth = w.encoderIntervalWidth;
            encoderAccumulator = w.encoderAccumulator;
            encoderAbsoluteAccumulator = w.encoderAbsoluteAccumulator;
            encoderQuadrature = w.encoderQuadrature;
            encoderAngle = w.encoderAngle;
            encoderInterval = w.encoderInterval;
            encoderMotionVelocity = w.encoderMotionVelocity;
            encoderMotionTime = w.encoderMotionTime;
        }
    }

    /** Draws the outline turned by the steering angle about the hub. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        PlanPolygons.paint(g, rotateAboutPivot(t, hubX, hubY, motionOrientationOffset), outline(),
                getFillColor(), getLineColor());
    }

    /**
     * The encoder state as an encoder-status event; with {@code clearOnReport} the accumulators are
     * zeroed after being reported.
     */
    public RsEncoderStatusEvent getEncoderStatusEvent(double simTime, int requestIndex, boolean clearOnReport) {
        RsEncoderStatusEvent event = new RsEncoderStatusEvent(simTime, requestIndex, getID(), encoderAccumulator,
                encoderAbsoluteAccumulator, encoderQuadrature, encoderInterval, encoderAngle, clearOnReport);
        if (clearOnReport) {
            encoderAccumulator = 0;
            encoderAbsoluteAccumulator = 0;
        }
        return event;
    }

    /** The distance the hub travels while the encoder counts {@code accumulator} intervals, metres. */
    public double mapAccumulatorToDisplacement(int accumulator) {
        if (encoderIntervalCount <= 0) {
            return 0.0;
        }
        return accumulator * encoderIntervalWidth * wheelRadius;
    }
}
