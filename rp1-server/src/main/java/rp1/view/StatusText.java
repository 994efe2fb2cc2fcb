package rp1.view;

import java.util.Locale;

import rp1.rossum.RsUnits;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;

/** The texts of the window's status line and coordinate read-out. */
final class StatusText {
    private StatusText() {
    }

    /**
     * Simulation time and every robot's pose, e.g.
     * {@code t = 12.500 s   ClientZero: x 1.234 m, y 2.000 m, heading 45.0 deg}.
     */
    static String describe(WorldSnapshot s, RsUnits units) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "t = %.3f s", s.simTime()));
        for (RobotSnapshot r : s.robots()) {
            b.append("   ").append(r.label()).append(": ");
            if (r.placed()) {
                double heading = Math.toDegrees(r.theta());
                b.append("x ").append(units.format(r.x()).trim())
                        .append(", y ").append(units.format(r.y()).trim())
                        .append(String.format(Locale.ROOT, ", heading %.1f deg", heading < 0 ? heading + 360.0 : heading));
            } else {
                b.append("not placed");
            }
        }
        return b.toString();
    }

    /** A coordinate read-out field: {@code x: } or {@code y: } and the value in the units. */
    static String readout(String axis, double metres, RsUnits units) {
        return axis + ": " + units.format(metres);
    }
}
