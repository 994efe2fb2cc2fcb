package rp1.rossum;

import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsMotionRequest;

/**
 * Differential steering (wheelchair style): two independently driven wheels on one axle, track
 * width apart, steer by turning at different speeds; equal and opposite speeds pivot the robot in
 * place. Linear velocity is the mean of the wheel velocities, rotational velocity their difference
 * over the track width.
 */
public class RsDifferentialSteering extends RsWheelSystem {
    private static final long serialVersionUID = 1L;

    private RsWheel leftWheel;
    private RsWheel rightWheel;

    /**
     * @param trackWidth distance between the drive wheels, metres
     * @param driveWheelRadius radius of the drive wheels, metres
     */
    public RsDifferentialSteering(double trackWidth, double driveWheelRadius) {
        this.trackWidth = trackWidth;
        this.driveWheelRadius = driveWheelRadius;
        name = "Differential Steering";
    }

    /**
     * Adds the two drive wheels on the axle: "left wheel" at y = +trackWidth/2 (built first, so its id
     * is one more than this system's when called right after the constructor) and "right wheel" at
     * y = -trackWidth/2, each drawn as a wheelRadius*2 by wheelWidth rectangle.
     */
    @Override
    public void addDefaultWheels(double wheelRadius, double wheelWidth) {
        RsWheel[] pair = addAxleWheels(0.0, wheelRadius, wheelWidth, "left wheel", "right wheel");
        leftWheel = pair[0];
        rightWheel = pair[1];
    }

    /**
     * Fits both default wheels with encoders of {@code nIntervals} intervals.
     *
     * @return {left, right} (elements null when nIntervals is not positive), or null when the default
     *         wheels have not been added
     */
    public RsEncoder[] addEncodersToDefaultWheels(int nIntervals) {
        if (leftWheel == null) {
            return null;
        }
        return new RsEncoder[] {leftWheel.addEncoder(nIntervals), rightWheel.addEncoder(nIntervals)};
    }

    /** A request from the wheels' linear velocities (m/s): v = (l + r)/2, omega = (r - l)/trackWidth. */
    public RsMotionRequest getMotionRequestUsingWheelVelocities(double vLeft, double vRight, double duration) {
        return new RsMotionRequest((vLeft + vRight) / 2.0, (vRight - vLeft) / trackWidth, duration);
    }

    /** A request from the wheels' rotational velocities (rad/s), times the drive-wheel radius. */
    public RsMotionRequest getMotionRequestUsingWheelRotationalVelocities(
            double rotLeft, double rotRight, double duration) {
        return getMotionRequestUsingWheelVelocities(rotLeft * driveWheelRadius, rotRight * driveWheelRadius, duration);
    }

    /**
     * An actuator-control request turning the wheels at these rotational velocities (rad/s) until
     * further notice: ACTIVATE with "leftRotationalVelocity" and "rightRotationalVelocity", or, when
     * both are 0, a HALT request without parameters (which RP1 0.60's sendActuatorControlRequest
     * could not send; use sendHaltRequest to stop).
     */
    public RsActuatorControlRequest getControlRequestForWheelRotation(double left, double right) {
        if (left == 0.0 && right == 0.0) {
            return new RsActuatorControlRequest(getID(), RsActuatorControlRequest.HALT);
        }
        RsActuatorControlRequest r = new RsActuatorControlRequest(getID(), RsActuatorControlRequest.ACTIVATE);
        r.addParameter("leftRotationalVelocity", left);
        r.addParameter("rightRotationalVelocity", right);
        return r;
    }

    /** values[0], values[1] = left and right wheel rotational velocities (rad/s); 300000 s. */
    @Override
    public RsMotionRequest getMotionRequestForActuatorControl(double[] values) {
        if (values == null || values.length < 2) {
            return null;
        }
        double v = driveWheelRadius * (values[0] + values[1]) / 2.0;
        double w = driveWheelRadius * (values[1] - values[0]) / trackWidth;
        return new RsMotionRequest(v, w, CONTROL_DURATION);
    }
}
