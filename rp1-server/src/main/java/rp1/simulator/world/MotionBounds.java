package rp1.simulator.world;

import rp1.rossum.request.RsMotionRequest;

/**
 * How far a motion may go: at most {@link #MAX_TRAVEL} metres and {@link #MAX_TURN} radians, its
 * duration cut to keep within both (docs/behavior.md section 5.2). Velocities and durations of any
 * finite size pass the wire (docs/protocol.md section 14), and their products did not stay finite or
 * exact: a drive of 2 m/s for 1e308 s overflowed the search for the walls in its way, and the robot
 * passed through them; a turn of 1e308 rad/s for 10 s gave the robot a pose of NaN. No plan is
 * anywhere near a million kilometres across, so no motion a robot could make in one is changed.
 */
final class MotionBounds {
    /** The longest path of one motion, metres. */
    static final double MAX_TRAVEL = 1.0e9;
    /** The most one motion turns, radians. */
    static final double MAX_TURN = 1.0e9;

    private MotionBounds() {
    }

    /** {@code q}, or {@code q} with its duration cut to the bounds when it would go or turn further. */
    static RsMotionRequest bounded(RsMotionRequest q) {
        double v = Math.abs(q.linearVelocity);
        double w = Math.abs(q.rotationalVelocity);
        double duration = q.duration;
        if (v * duration > MAX_TRAVEL) {
            duration = MAX_TRAVEL / v;
        }
        if (w * duration > MAX_TURN) {
            duration = MAX_TURN / w;
        }
        return duration == q.duration ? q : new RsMotionRequest(q.linearVelocity, q.rotationalVelocity, duration);
    }
}
