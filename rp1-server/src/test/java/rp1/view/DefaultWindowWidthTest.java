package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Insets;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsUnits;
import rp1.simulator.snapshot.RobotSnapshot;

/**
 * A new window is wide enough for the status line of every shipped demo, measured with the status
 * line's own font, and never narrower than RP1 0.60's window nor wider than the screen.
 */
class DefaultWindowWidthTest {
    private static final Insets NO_BORDERS = new Insets(0, 0, 0, 0);
    private static final int SCREEN = 1920;

    /** The widest status line {@code robotName} shows anywhere on {@code plan}, in pixels. */
    private static int widestLine(StatusPanel status, RsPlan plan, RsUnits units, String robotName) {
        RsRectangle b = plan.getBounds();
        int widest = 0;
        for (int i = 0; i <= 20; i++) {
            for (int j = 0; j <= 20; j++) {
                double x = b.x + b.width * i / 20.0;
                double y = b.y + b.height * j / 20.0;
                for (double heading = -180.0; heading < 180.0; heading += 22.5) {
                    RobotSnapshot r = new RobotSnapshot(1, robotName, true, x, y, Math.toRadians(heading), List.of());
                    String line = StatusText.describe(3600.0 + i + j / 1000.0, true, List.of(r), units);
                    widest = Math.max(widest, status.widthFor(List.of(line)));
                }
            }
        }
        return widest;
    }

    private static int defaultWidth(StatusPanel status, RsPlan plan, RsUnits units) {
        return SimulatorWindow.defaultWidth(status.widthFor(StatusText.samples(plan, units)), NO_BORDERS, SCREEN);
    }

    /** Each shipped demo's plan and the name its robot's body has. */
    @Test
    void theStatusLineOfEveryShippedDemoFitsTheDefaultWindow() throws Exception {
        String[][] demos = {
                {"WhiteRoom.txt", "ClientZero"},
                {"contest.txt", "ClientZero"},
                {"linetrack.txt", "LineTracker"},
                {"ackerman.txt", "Ackerman car"},
        };
        for (String[] demo : demos) {
            RsPlan plan = Worlds.plan(demo[0]);
            DisplayUnits units = DisplayUnits.of(plan.getUnits());
            StatusPanel status = new StatusPanel(units);
            int needed = widestLine(status, plan, units.units(), demo[1]);
            int width = defaultWidth(status, plan, units.units());
            assertTrue(needed <= width, demo[1] + " on " + demo[0] + " needs " + needed + " px, the window has " + width);
        }
    }

    @Test
    void theContestArenaInInchesNeedsMoreThanTheOriginalsWidth() throws Exception {
        RsPlan contest = Worlds.plan("contest.txt");
        DisplayUnits inches = DisplayUnits.of(contest.getUnits());
        StatusPanel status = new StatusPanel(inches);
        assertTrue(widestLine(status, contest, inches.units(), "ClientZero") > SimulatorWindow.MIN_DEFAULT_WIDTH,
                "the 500-pixel window of RP1 0.60 cut this line off");
        assertTrue(defaultWidth(status, contest, inches.units()) > SimulatorWindow.MIN_DEFAULT_WIDTH);
    }

    @Test
    void theWidthCoversTheFrameBordersButStaysBetweenTheOriginalsAndTheScreens() {
        assertEquals(620, SimulatorWindow.defaultWidth(600, new Insets(30, 10, 5, 10), SCREEN));
        assertEquals(500, SimulatorWindow.defaultWidth(300, NO_BORDERS, SCREEN), "never below RP1 0.60's 500 pixels");
        assertEquals(800, SimulatorWindow.defaultWidth(1200, NO_BORDERS, 800), "never wider than the screen");
    }
}
