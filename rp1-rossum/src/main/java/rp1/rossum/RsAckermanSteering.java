package rp1.rossum;

import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsMotionRequest;

/**
 * Ackerman (automobile) steering: driven wheels and steerable wheels whose angle sets the turn
 * radius. The steering angle is the central one (a virtual wheel on the centre line); the inner
 * wheel turns more. The steering base b is the wheel base, or half of it with dual (front and rear)
 * steering. The inner-wheel limit is capped at 85 degrees and gives the minimum turn radius
 * b / tan(innerMax) + trackWidth/2 and the central limit atan(b / minTurnRadius) (behavior.md
 * section 5.6). Such a robot cannot pivot, so {@link #getMotionRequest} and
 * {@link #getMotionRequestForPivot} return null.
 */
public class RsAckermanSteering extends RsWheelSystem {
    private static final long serialVersionUID = 1L;

    /** The inner-wheel steering limit is capped at 85 degrees. */
    private static final double MAX_INNER_ANGLE = Math.toRadians(85.0);
    /** Steering angles at most this large (radians) drive straight. */
    private static final double STRAIGHT_ANGLE = 1.0e-5;

    /** Central steering limit, radians. */
    protected double maxAbsSteeringAngle;
    /**
     * Smallest turning radius of the body origin, metres, from the inner wheel's steering limit.
     */
    protected double minTurnRadius;
    /** Whether the rear wheels steer too. */
    protected boolean dualSteering;
    /** The central steering angle the wheels are drawn at, radians. */
    protected double depictionSteeringAngle;
    /** Whether {@link #addDefaultWheels} has added the four drawn wheels. */
    protected boolean defaultWheelsAdded;
    /**
     * The steering limit this system was decoded from (NaN if it was built, not decoded). Decoding
     * derives a smaller limit from the one on the wire, as RP1 0.60's simulator does; encoding a
     * decoded system writes the wire's value back, so that a body written into a recording is, read
     * again, the body the simulator had (encoding the derived limit shrank it once more at every replay).
     */
    double decodedFrom = Double.NaN;

    /**
     * @param trackWidth distance between left and right wheels, metres
     * @param wheelBase distance between the front and rear axles, metres
     * @param driveWheelRadius radius of the driven wheels, metres
     * @param maxAbsInnerWheelSteeringAngle steering limit of the inner wheel, radians (capped at 85 degrees)
     * @param dualSteering whether the rear wheels steer too
     */
    public RsAckermanSteering(double trackWidth, double wheelBase, double driveWheelRadius,
                              double maxAbsInnerWheelSteeringAngle, boolean dualSteering) {
        this.trackWidth = trackWidth;
        this.wheelBase = wheelBase;
        this.driveWheelRadius = driveWheelRadius;
        this.dualSteering = dualSteering;
        double innerMaxAngle = Math.min(maxAbsInnerWheelSteeringAngle, MAX_INNER_ANGLE);
        minTurnRadius = steeringBase() / Math.tan(innerMaxAngle) + trackWidth / 2.0;
        maxAbsSteeringAngle = Math.atan(steeringBase() / minTurnRadius);
        name = "Ackerman Steering";
    }

    /** The wheel base, or half of it with dual steering. */
    private double steeringBase() {
        return dualSteering ? wheelBase / 2.0 : wheelBase;
    }

    /** The tightest turn radius, metres: b / tan(innerMax) + trackWidth/2. */
    public double getMinTurnRadius() {
        return minTurnRadius;
    }

    /** The central steering limit derived from the inner-wheel limit, radians. */
    public double getMaxAbsSteeringAngle() {
        return maxAbsSteeringAngle;
    }

    /** Whether the rear wheels steer too. */
    public boolean isDualSteering() {
        return dualSteering;
    }

    /** The central steering angle the wheels are drawn at, radians. */
    public double getSteeringAngle() {
        return depictionSteeringAngle;
    }

    /**
     * Adds four wheels as RP1 0.60 builds them, in this order: rear left, rear right, front left,
     * front right (left is y = +trackWidth/2). Without dual steering the rear axle is the body's y
     * axis (x = 0) and the front axle is at x = wheelBase; with dual steering the axles are at
     * x = -wheelBase/2 and +wheelBase/2. Each wheel is drawn as a wheelRadius*2 by wheelWidth
     * rectangle on its hub with a stub axle (stubLength by stubWidth) reaching from the hub towards
     * the centre line. The wheels keep the default name "Unnamed" and all four, rear ones included,
     * get the derived central limit {@link #getMaxAbsSteeringAngle()} as their steering limit, so
     * all report themselves steerable. A wheel on the body's y axis is never turned by
     * {@link #setSteeringAngle}, so without dual steering only the front pair is drawn steered.
     */
    public void addDefaultWheels(double wheelRadius, double wheelWidth, double stubLength, double stubWidth) {
        double rearX = dualSteering ? -wheelBase / 2.0 : 0.0;
        double frontX = dualSteering ? wheelBase / 2.0 : wheelBase;
        addDefaultWheel(rearX, 1, wheelRadius, wheelWidth, stubLength, stubWidth);
        addDefaultWheel(rearX, -1, wheelRadius, wheelWidth, stubLength, stubWidth);
        addDefaultWheel(frontX, 1, wheelRadius, wheelWidth, stubLength, stubWidth);
        addDefaultWheel(frontX, -1, wheelRadius, wheelWidth, stubLength, stubWidth);
        defaultWheelsAdded = true;
        setSteeringAngle(depictionSteeringAngle);
    }

    /** side = +1 for the left wheel (y > 0), -1 for the right one. */
    private void addDefaultWheel(double x, int side, double radius, double width, double stubLength, double stubWidth) {
        double y = side * trackWidth / 2.0;
        double[] p = {
            -radius, width / 2, -radius, -width / 2, -stubWidth / 2, -width / 2, -stubWidth / 2, -stubLength,
            stubWidth / 2, -stubLength, stubWidth / 2, -width / 2, radius, -width / 2, radius, width / 2};
        for (int i = 0; i < p.length; i += 2) {
            p[i] += x;
            p[i + 1] = y + side * p[i + 1];
        }
        addWheel(new RsWheel(p, p.length / 2, x, y, radius, maxAbsSteeringAngle));
    }

    /**
     * Sets the central steering angle (radians, positive = left), limited to the central limit, and
     * turns each steerable wheel to its Ackerman angle: a wheel at (x, y) turns by
     * atan2(|x|, |rho - y|) with rho = b / tan(angle), negated if rho - y is negative and again if x is.
     */
    public void setSteeringAngle(double angle) {
        depictionSteeringAngle = clampSteering(angle);
        double rho = steeringBase() / Math.tan(depictionSteeringAngle);
        for (RsWheel w : wheels) {
            if (w.isWheelSteerable()) {
                w.setOrientation(depictionSteeringAngle == 0.0 ? 0.0 : wheelAngle(w.getX(), w.getY(), rho));
            }
        }
    }

    private static double wheelAngle(double x, double y, double rho) {
        double a = Math.atan2(Math.abs(x), Math.abs(rho - y));
        if (rho - y < 0) {
            a = -a;
        }
        return x < 0 ? -a : a;
    }

    private double clampSteering(double angle) {
        return Math.max(-maxAbsSteeringAngle, Math.min(angle, maxAbsSteeringAngle));
    }

    /** b / tan(angle) for the limited angle; infinite for a zero angle. Negative for right turns. */
    public double getTurnRadiusForSteeringAngle(double angle) {
        return steeringBase() / Math.tan(clampSteering(angle));
    }

    /** Drive-wheel rotational velocity (rad/s) for a linear velocity: v / r. */
    public double mapVelocityToWheelRotationalVelocity(double velocity) {
        return velocity / driveWheelRadius;
    }

    /** Drive-wheel revolutions per minute for a linear velocity: 60 v / (2 pi r). */
    public double mapVelocityToWheelRPM(double velocity) {
        return 60.0 * velocity / (2.0 * Math.PI * driveWheelRadius);
    }

    /** Linear velocity for drive-wheel revolutions per minute: rpm 2 pi r / 60. */
    public double mapWheelRPMToVelocity(double rpm) {
        return rpm * 2.0 * Math.PI * driveWheelRadius / 60.0;
    }

    /**
     * A request to drive at {@code velocity} m/s with the central steering angle (limited) for
     * {@code duration} s: omega = velocity / turn radius, or 0 when |angle| is at most 1e-5.
     */
    public RsMotionRequest getMotionRequestUsingVelocityAndSteeringAngle(
            double velocity, double steeringAngle, double duration) {
        double w = Math.abs(steeringAngle) <= STRAIGHT_ANGLE
                ? 0.0 : velocity / getTurnRadiusForSteeringAngle(steeringAngle);
        return new RsMotionRequest(velocity, w, duration);
    }

    /** As {@link #getMotionRequestUsingVelocityAndSteeringAngle}, the velocity given as drive-wheel rad/s. */
    public RsMotionRequest getMotionRequestUsingWheelRotationalVelocityAndSteeringAngle(
            double wheelRotationalVelocity, double steeringAngle, double duration) {
        return getMotionRequestUsingVelocityAndSteeringAngle(
                wheelRotationalVelocity * driveWheelRadius, steeringAngle, duration);
    }

    /**
     * An actuator-control request (ACTIVATE) with "driveRotationalVelocity" (rad/s) and
     * "steeringAngle" (radians), in that order.
     */
    public RsActuatorControlRequest getControlRequestForWheelRotationAndSteeringAngle(
            double driveRotationalVelocity, double steeringAngle) {
        RsActuatorControlRequest r = new RsActuatorControlRequest(getID(), RsActuatorControlRequest.ACTIVATE);
        r.addParameter("driveRotationalVelocity", driveRotationalVelocity);
        r.addParameter("steeringAngle", steeringAngle);
        return r;
    }

    /** Always null: general goal seeking is not implemented for Ackerman steering. */
    @Override
    public RsMotionRequest getMotionRequest(double x, double y, double speed) {
        return null;
    }

    /** Always null: an Ackerman robot cannot pivot. */
    @Override
    public RsMotionRequest getMotionRequestForPivot(double x, double y, double speed) {
        return null;
    }

    /**
     * values[0] = drive-wheel rotational velocity (rad/s), values[1] = central steering angle: the
     * wheels are steered (limited), then v = r values[0] and omega = v tan(angle) / b (0 when
     * |angle| is at most 1e-5), for 300000 s.
     */
    @Override
    public RsMotionRequest getMotionRequestForActuatorControl(double[] values) {
        if (values == null || values.length < 2) {
            return null;
        }
        setSteeringAngle(values[1]);
        double v = driveWheelRadius * values[0];
        double w = Math.abs(depictionSteeringAngle) <= STRAIGHT_ANGLE
                ? 0.0 : v * Math.tan(depictionSteeringAngle) / steeringBase();
        return new RsMotionRequest(v, w, CONTROL_DURATION);
    }

    /** A placement straightens the wheels and the steering. */
    @Override
    public void resetStateData() {
        super.resetStateData();
        depictionSteeringAngle = 0.0;
    }

    @Override
    public void copyStateData(RsBodyPart source) {
        super.copyStateData(source);
        if (source instanceof RsAckermanSteering) {
            depictionSteeringAngle = ((RsAckermanSteering) source).depictionSteeringAngle;
        }
    }
}
