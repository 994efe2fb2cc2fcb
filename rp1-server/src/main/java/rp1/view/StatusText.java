package rp1.view;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsUnits;
import rp1.simulator.snapshot.RobotSnapshot;

/** The texts of the window's status line and coordinate read-out. */
final class StatusText {
    /** A robot name as long as the longest among the shipped demos' robots. */
    static final String SAMPLE_ROBOT_NAME = "Ackerman car";
    /** A time with as many digits as a demo left running for well over an hour shows. */
    static final double SAMPLE_TIME = 9999.999;

    private StatusText() {
    }

    /**
     * The simulation time, whether the run is paused (Run menu), and the pose of every robot, e.g.
     * {@code t = 12.500 s   ClientZero: x 1.234 m, y 2.000 m, heading 45.0 deg}. The time is the
     * clock's, not the snapshot's: it moves on while the robots stand still and no snapshot is taken.
     */
    static String describe(double simTime, boolean paused, List<RobotSnapshot> robots, RsUnits units) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "t = %.3f s", simTime));
        if (paused) {
            b.append(" (paused)");
        }
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

    /**
     * Candidates for the widest status line a shipped demo shows on {@code plan}: one robot with the
     * longest demo name at each corner of the plan (the coordinates with the most digits and signs),
     * heading 359.9 degrees, at {@link #SAMPLE_TIME}, paused. Which is widest depends on the font; the
     * window's default width is made to fit them all.
     */
    static List<String> samples(RsPlan plan, RsUnits units) {
        RsRectangle b = plan.getBounds();
        double heading = Math.toRadians(-0.1);
        List<String> lines = new ArrayList<>();
        for (double x : new double[] {b.x, b.x + b.width}) {
            for (double y : new double[] {b.y, b.y + b.height}) {
                RobotSnapshot robot = new RobotSnapshot(1, SAMPLE_ROBOT_NAME, true, x, y, heading, List.of());
                lines.add(describe(SAMPLE_TIME, true, List.of(robot), units));
            }
        }
        return lines;
    }

    /** A coordinate read-out field: {@code x: } or {@code y: } and the value in the units. */
    static String readout(String axis, double metres, RsUnits units) {
        return axis + ": " + units.format(metres);
    }
}
