package rp1demo.navigation;

import java.util.Locale;

/**
 * Where a robot is: position in metres and heading in radians, anticlockwise from the +x axis.
 *
 * @param x       metres
 * @param y       metres
 * @param heading radians
 */
public record Pose(double x, double y, double heading) {

    /** Distance from this position to (px, py), metres. */
    public double distanceTo(double px, double py) {
        return Math.hypot(px - x, py - y);
    }

    /** The turn (in (-pi, pi]) that would point the robot at (px, py). */
    public double turnTowards(double px, double py) {
        return normalize(Math.atan2(py - y, px - x) - heading);
    }

    /** The point (px, py) in the robot's own frame: x ahead, y to the left. */
    public double[] toRobotFrame(double px, double py) {
        double dx = px - x;
        double dy = py - y;
        double c = Math.cos(heading);
        double s = Math.sin(heading);
        return new double[] {c * dx + s * dy, -s * dx + c * dy};
    }

    /** The angle {@code a} brought into (-pi, pi]. */
    public static double normalize(double a) {
        double r = Math.IEEEremainder(a, 2.0 * Math.PI);
        return r <= -Math.PI ? r + 2.0 * Math.PI : r;
    }

    /**
     * The pose as the demos log it: the heading counter-clockwise from the x axis, 0 to 360 degrees,
     * as the simulator's window shows it, whether the event carried it as given in the plan (a
     * placement at 225) or as the model keeps it (-135 after a motion).
     */
    @Override
    public String toString() {
        double degrees = Math.toDegrees(heading) % 360.0;
        if (degrees < 0.0) {
            degrees += 360.0;
        }
        return String.format(Locale.ROOT, "(%.3f, %.3f) heading %.1f deg", x, y, degrees);
    }
}
