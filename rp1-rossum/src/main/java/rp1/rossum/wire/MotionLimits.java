package rp1.rossum.wire;

/**
 * How a motion request (v, omega, T) is classified (docs/behavior.md section 5.2): the body turns a
 * request into a null motion, a straight line or an arc by these limits, and the server chooses the
 * walls a motion's collision search is offered by the same ones. Both must agree exactly: a turn rate
 * just under {@link #STRAIGHT_LIMIT} drives straight, and a wall beyond an arc's circle must not be
 * left out of a search for a line.
 */
public final class MotionLimits {
    /** Durations (s), speeds (m/s) and turn rates (rad/s) below this make a request a null motion. */
    public static final double NULL_LIMIT = 1.0e-4;
    /** Turn rates below this, rad/s (0.1 degree per second), make a request a straight line. */
    public static final double STRAIGHT_LIMIT = 0.1 * Math.PI / 180.0;

    private MotionLimits() {
    }
}
