package rp1.simulator.noise;

import static rp1.rossum.wire.MotionLimits.NULL_LIMIT;
import static rp1.rossum.wire.MotionLimits.STRAIGHT_LIMIT;

import rp1.rossum.request.RsMotionRequest;

/**
 * Dead reckoning: where a motion request takes a robot in a given time, by the rules the simulator
 * turns requests into motions (behavior.md section 5.2): a null motion for a very short or very slow
 * request, a straight line for a turn rate under 0.1 degree per second, else an arc about a pivot
 * |v / omega| to the side of omega's sign, the heading turning by omega (negated when backing).
 */
final class Odometry {
    private Odometry() {
    }

    /** The pose {x, y, heading} after {@code elapsed} seconds of {@code request} from (x, y, theta). */
    static double[] after(double x, double y, double theta, RsMotionRequest request, double elapsed) {
        double v = request.linearVelocity;
        double w = request.rotationalVelocity;
        if (request.duration < NULL_LIMIT || Math.abs(v) < NULL_LIMIT && Math.abs(w) < NULL_LIMIT) {
            return new double[] {x, y, theta};
        }
        double cos = Math.cos(theta);
        double sin = Math.sin(theta);
        if (Math.abs(w) < STRAIGHT_LIMIT) {
            return new double[] {x + v * elapsed * cos, y + v * elapsed * sin, theta};
        }
        double rho = Math.abs(v / w) * Math.signum(w);
        double px = x - rho * sin;
        double py = y + rho * cos;
        double phi = (v < 0 ? -w : w) * elapsed;
        double c = Math.cos(phi);
        double s = Math.sin(phi);
        double dx = x - px;
        double dy = y - py;
        return new double[] {px + c * dx - s * dy, py + s * dx + c * dy, Math.atan2(Math.sin(theta + phi), Math.cos(theta + phi))};
    }
}
