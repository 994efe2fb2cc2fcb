package rp1.rossum;

import static rp1.rossum.wire.MotionLimits.NULL_LIMIT;
import static rp1.rossum.wire.MotionLimits.STRAIGHT_LIMIT;

import rp1.rossum.request.RsMotionRequest;

/**
 * The arithmetic between motion requests (v, omega, T) and motions: how the simulator interprets a
 * request (behavior.md section 5.2) and how the client helpers aim for a goal point (section 5.6).
 */
final class MotionRequests {
    /** A goal farther than this turn radius (metres) is approached in a straight line. */
    private static final double MAX_ARC_RADIUS = 1000.0;
    /** Pivots always turn at 90 degrees per second. */
    private static final double PIVOT_RATE = Math.PI / 2.0;

    private MotionRequests() {
    }

    /**
     * The motion a request produces when it starts at {@code time} where {@code previous} is then:
     * null, straight line, or arc about a pivot ({@code |v/omega|} to the side given by the sign of
     * omega; heading turns by omega T, negated when backing).
     */
    static RsMotion motionFor(RsMotion previous, double time, RsMotionRequest request) {
        double v = request.linearVelocity;
        double w = request.rotationalVelocity;
        double duration = request.duration;
        if (duration < NULL_LIMIT || Math.abs(v) < NULL_LIMIT && Math.abs(w) < NULL_LIMIT) {
            return new RsMotionNull(previous, time);
        }
        RsTransform start = previous == null ? new RsTransform() : previous.getStateAtTime(time);
        double theta = start.getTheta();
        double cos = Math.cos(theta);
        double sin = Math.sin(theta);
        if (Math.abs(w) < STRAIGHT_LIMIT) {
            return new RsMotionLine(previous, time, duration, new RsVector(cos, sin), v);
        }
        double rho = Math.abs(v / w) * Math.signum(w);
        RsPoint pivot = new RsPoint(start.m13 - rho * sin, start.m23 + rho * cos);
        return new RsMotionCircle(previous, time, duration, pivot, v < 0 ? -w : w);
    }

    /**
     * A request that takes the robot to (x, y) (robot coordinates) at {@code speed}: straight if y is
     * 0 or the arc would be wider than 1000 m, else along the arc tangent to the heading through the
     * goal, backing along it if the goal is behind. Null for a speed below 1e-6, a goal closer than
     * sqrt(0.001) m off the axis, a path shorter than 0.1 mm or a duration under 1 ms.
     */
    static RsMotionRequest towards(double x, double y, double speed) {
        double s = Math.abs(speed);
        if (s < 1.0e-6) {
            return null;
        }
        if (y == 0.0) {
            return straight(x, s);
        }
        double s2 = x * x + y * y;
        if (s2 < 0.001) {
            return null;
        }
        double radius = s2 / (2.0 * Math.abs(y));
        if (radius > MAX_ARC_RADIUS) {
            return straight(x, s);
        }
        double alpha = Math.PI - 2.0 * Math.atan2(Math.abs(x), Math.abs(y));
        double distance = alpha * radius;
        double duration = distance / s;
        if (tooShort(duration) || distance < NULL_LIMIT) {
            return null;
        }
        double w = (y > 0 ? alpha : -alpha) / duration;
        return new RsMotionRequest(x < 0 ? -s : s, w, duration);
    }

    private static RsMotionRequest straight(double x, double speed) {
        double distance = Math.abs(x);
        double duration = distance / speed;
        if (tooShort(duration) || distance < NULL_LIMIT) {
            return null;
        }
        return new RsMotionRequest(x < 0 ? -speed : speed, 0.0, duration);
    }

    /** A turn in place to face (x, y) at 90 degrees per second; null if it would take under 1 ms. */
    static RsMotionRequest pivotTowards(double x, double y) {
        double beta = Math.atan2(y, x);
        double w = beta >= 0 ? PIVOT_RATE : -PIVOT_RATE;
        double duration = beta / w;
        return tooShort(duration) ? null : new RsMotionRequest(0.0, w, duration);
    }

    private static boolean tooShort(double duration) {
        return Math.floor(1000.0 * duration) < 1.0;
    }
}
