package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.swing.JMenu;
import javax.swing.JMenuItem;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.simulator.Simulation;
import rp1.simulator.scenario.Scenario;

/** The window's Run menu pauses, steps and sets the speed through the Simulation. No display needed. */
@Timeout(60)
class RunMenuTest {

    private static JMenuItem item(JMenu menu, String text) {
        for (int i = 0; i < menu.getItemCount(); i++) {
            JMenuItem item = menu.getItem(i);
            if (item != null && text.equals(item.getText())) {
                return item;
            }
        }
        throw new AssertionError("no item " + text + " in " + menu.getText());
    }

    @Test
    void pauseResumesStepPausesAndTheSpeedsAreSet() {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            Simulation sim = s.simulation();
            JMenu run = Menus.runMenu(sim);
            assertEquals("Run", run.getText());
            JMenu speed = (JMenu) item(run, "Speed");
            assertTrue(item(speed, "Max").isSelected(), "a lockstep run is at max");
            assertFalse(item(speed, "1\u00d7").isSelected());

            item(run, Menus.PAUSE).doClick();
            assertTrue(sim.isPaused());
            item(run, Menus.RESUME).doClick();
            assertFalse(sim.isPaused());
            assertEquals(Menus.PAUSE, run.getItem(0).getText());

            item(run, "Step").doClick();
            assertTrue(sim.isPaused(), "a step leaves the run paused");
            assertEquals(Menus.RESUME, run.getItem(0).getText());

            item(speed, "10\u00d7").doClick();
            assertEquals(10.0, sim.getSpeed());
            item(speed, "1\u00d7").doClick();
            assertEquals(1.0, sim.getSpeed());
            item(speed, "Max").doClick();
            assertEquals(Double.POSITIVE_INFINITY, sim.getSpeed());
        }
    }
}
