package rp1.view;

import java.util.List;
import java.util.Locale;

import rp1.rossum.RsUnits;
import rp1.simulator.snapshot.RobotSnapshot;

/** The texts of the window's status line and coordinate read-out. */
final class StatusText {
    private StatusText() {
    }

    /**
     * The simulation time and the pose of every robot, e.g.
     * {@code t = 12.500 s   ClientZero: x 1.234 m, y 2.000 m, heading 45.0 deg}. The time is the
     * clock's, not the snapshot's: it moves on while the robots stand still and no snapshot is taken.
     */
    static String describe(double simTime, List<RobotSnapshot> robots, RsUnits units) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "t = %.3f s", simTime));
        for (RobotSnapshot r : robots) {
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
