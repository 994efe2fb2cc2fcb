package rp1.simulator.noise;

import rp1.rossum.RsTransform;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Wheel slip, after Stage's odometry error model: each motion the robot makes covers its commanded
 * distance and turn times (1 + e), with e drawn per motion from a normal of the settings' sigma (one
 * for the distance, one for the turn). The world moves the robot along the slipped motion, its true
 * pose; the robot's motion events report the pose it believes it has, dead reckoned from the
 * commanded motions since it was last placed ({@link Odometry}).
 */
final class MotionNoise {
    private final NoiseSettings settings;
    private final Draws distance;
    private final Draws turn;
    /** The believed pose where the current commanded motion began, x, y, heading. */
    private double x;
    private double y;
    private double theta;
    private double startTime;
    private RsMotionRequest commanded;
    /** How long the commanded motion ran: its duration until it stops. */
    private double ran;

    MotionNoise(NoiseSettings settings, long seed, int robot) {
        this.settings = settings;
        distance = new Draws(seed, robot, Draws.Quantity.SLIP_DISTANCE);
        turn = new Draws(seed, robot, Draws.Quantity.SLIP_TURN);
    }

    /** The robot was put at this pose (by its client or the plan): it knows where it is. */
    void placed(double time, double px, double py, double orientation) {
        x = px;
        y = py;
        theta = orientation;
        startTime = time;
        commanded = null;
    }

    /** The motion the robot really makes for {@code request}: its distance and turn slipped. */
    RsMotionRequest slip(RsMotionRequest request) {
        double d = 1.0 + distance.gaussian(settings.slipDistanceSigma);
        double t = 1.0 + turn.gaussian(settings.slipTurnSigma);
        return new RsMotionRequest(request.linearVelocity * d, request.rotationalVelocity * t, request.duration);
    }

    /** The commanded motion {@code request} starts at {@code time}: the belief follows it from where it is. */
    void begin(double time, RsMotionRequest request) {
        double[] at = believedAt(time);
        x = at[0];
        y = at[1];
        theta = at[2];
        startTime = time;
        commanded = request;
        ran = request.duration;
    }

    /** The started event with the believed start pose. */
    RsMotionStartedEvent started(RsMotionStartedEvent truth) {
        double[] at = believedAt(truth.simTime);
        return new RsMotionStartedEvent(truth.simTime, truth.linearVelocity, truth.rotationalVelocity, truth.duration,
                at[0], at[1], at[2]);
    }

    /** The halted event with the believed pose where the motion stopped (it runs no further). */
    RsMotionHaltedEvent halted(RsMotionHaltedEvent truth) {
        if (commanded != null) {
            ran = Math.min(ran, Math.max(0.0, truth.simTime - startTime));
        }
        double[] at = believedAt(truth.simTime);
        return new RsMotionHaltedEvent(truth.simTime, truth.causeOfHalt, at[0], at[1], at[2], truth.duration);
    }

    /** The believed pose at {@code time}. */
    RsTransform believedPose(double time) {
        double[] at = believedAt(time);
        return new RsTransform(at[2], at[0], at[1]);
    }

    private double[] believedAt(double time) {
        if (commanded == null) {
            return new double[] {x, y, theta};
        }
        double elapsed = Math.max(0.0, Math.min(time - startTime, ran));
        return Odometry.after(x, y, theta, commanded, elapsed);
    }
}
