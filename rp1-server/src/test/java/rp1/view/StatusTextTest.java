package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsFeet;
import rp1.rossum.RsInches;
import rp1.rossum.RsKilometers;
import rp1.rossum.RsMeters;
import rp1.rossum.RsPlan;
import rp1.simulator.snapshot.RobotSnapshot;

/** The status line, the coordinate read-out and the units checked at first (behavior.md section 10). */
class StatusTextTest {

    @Test
    void theStatusLineShowsTheTimeAndEveryRobotsPoseInTheChosenUnits() {
        List<RobotSnapshot> robots = List.of(new RobotSnapshot(1, "ClientZero", true, 1.234, 2.0, Math.toRadians(-90), List.of()),
                new RobotSnapshot(2, "robot 2", false, 0, 0, 0, List.of()));
        assertEquals("t = 12.500 s   ClientZero: x 1.234 m, y 2.000 m, heading 270.0 deg   robot 2: not placed",
                StatusText.describe(12.5, false, robots, new RsMeters()));
        assertEquals("t = 12.500 s   ClientZero: x 4 ft  0-19/32 in, y 6 ft  6-24/32 in, heading 270.0 deg   robot 2: not placed",
                StatusText.describe(12.5, false, robots, new RsFeet()));
        assertEquals("t = 12.500 s (paused)   ClientZero: x 1.234 m, y 2.000 m, heading 270.0 deg   robot 2: not placed",
                StatusText.describe(12.5, true, robots, new RsMeters()), "a paused run says so after the time");
    }

    @Test
    void theReadOutUsesTheUnitsFormats() {
        assertEquals("x:    1.234 m", StatusText.readout("x", 1.234, new RsMeters()));
        assertEquals("y: -  48-19/32 in", StatusText.readout("y", -1.2342, new RsInches()));
    }

    @Test
    void thePlansUnitsAreCheckedWhenTheWindowOpens() {
        assertEquals(DisplayUnits.METERS, DisplayUnits.of(new RsMeters()));
        assertEquals(DisplayUnits.FEET, DisplayUnits.of(new RsFeet()));
        assertEquals(DisplayUnits.INCHES, DisplayUnits.of(new RsInches()));
        assertEquals(DisplayUnits.METERS, DisplayUnits.of(new RsKilometers()), "kilometres are shown in metres");
    }

    @Test
    void anUncaptionedPlanGetsTheOriginalsTitle() {
        RsPlan plan = new RsPlan();
        assertEquals("Rossum's Playhouse -- Untitled Plan", SimulatorWindow.title(plan));
        plan.setCaption("White Room (RP1 rev. 0.4)");
        assertEquals("White Room (RP1 rev. 0.4)", SimulatorWindow.title(plan));
    }

    @Test
    void theStatusPanelSaysWhatTheMouseDoes() {
        StatusPanel panel = new StatusPanel(DisplayUnits.METERS);
        java.util.List<String> labels = new java.util.ArrayList<>();
        collectLabels(panel, labels);
        assertTrue(labels.stream().anyMatch(t -> t.startsWith("left-click: send the robot there")), labels.toString());
    }

    private static void collectLabels(java.awt.Container c, java.util.List<String> into) {
        for (java.awt.Component child : c.getComponents()) {
            if (child instanceof javax.swing.JLabel label) {
                into.add(label.getText());
            } else if (child instanceof java.awt.Container inner) {
                collectLabels(inner, into);
            }
        }
    }
}
