package rp1.view;

import java.awt.GraphicsEnvironment;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.util.function.Consumer;

import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;

import rp1.simulator.Simulation;

/**
 * The window's menus: those of RP1 0.60 (File → Exit, View → Units, Actions → Remove Paint Trails)
 * plus View → Zoom In, Zoom Out and Fit, and the Run menu: Pause/Resume, Step (one modelling interval)
 * and Speed (1×, 10×, max), which only change how fast simulated time passes on the wall clock.
 */
final class Menus {
    private Menus() {
    }

    /**
     * @param units        the units checked at first
     * @param unitsChosen  told when the user picks other units
     * @param canvas       zoomed by the View menu
     * @param simulation   paused, stepped and sped up by the Run menu; its trails removed by Actions
     * @param exit         run by File → Exit
     */
    static JMenuBar build(DisplayUnits units, Consumer<DisplayUnits> unitsChosen, PlanCanvas canvas,
                          Simulation simulation, Runnable exit) {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.add(item("Exit", KeyEvent.VK_Q, exit));
        JMenu view = new JMenu("View");
        view.add(unitsMenu(units, unitsChosen));
        view.addSeparator();
        view.add(item("Zoom In", KeyEvent.VK_EQUALS, canvas::zoomIn));
        view.add(item("Zoom Out", KeyEvent.VK_MINUS, canvas::zoomOut));
        view.add(item("Fit", KeyEvent.VK_0, canvas::fit));
        JMenu actions = new JMenu("Actions");
        actions.add(item("Remove Paint Trails", 0, simulation::removePaintTrails));
        bar.add(file);
        bar.add(view);
        bar.add(runMenu(simulation));
        bar.add(actions);
        return bar;
    }

    /** The speeds the Run menu offers, in simulated seconds per wall second (infinity: max). */
    private static final double[] SPEEDS = {1.0, 10.0, Double.POSITIVE_INFINITY};

    static JMenu runMenu(Simulation simulation) {
        JMenu menu = new JMenu("Run");
        JMenuItem pause = item(PAUSE, KeyEvent.VK_P, () -> { });
        Runnable showState = () -> pause.setText(simulation.isPaused() ? RESUME : PAUSE);
        pause.addActionListener(e -> {
            if (simulation.isPaused()) {
                simulation.resume();
            } else {
                simulation.pause();
            }
            showState.run();
        });
        menu.add(pause);
        menu.add(item("Step", KeyEvent.VK_T, () -> {
            simulation.stepOneInterval();
            showState.run();
        }));
        menu.addSeparator();
        JMenu speed = new JMenu("Speed");
        ButtonGroup group = new ButtonGroup();
        double initial = simulation.getSpeed();
        for (double s : SPEEDS) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(speedLabel(s), Double.compare(s, initial) == 0);
            item.addActionListener(e -> simulation.setSpeed(s));
            group.add(item);
            speed.add(item);
        }
        menu.add(speed);
        return menu;
    }

    static final String PAUSE = "Pause";
    static final String RESUME = "Resume";

    static String speedLabel(double speed) {
        return Double.isInfinite(speed) ? "Max" : String.format("%.0f\u00d7", speed);
    }

    private static JMenu unitsMenu(DisplayUnits initial, Consumer<DisplayUnits> chosen) {
        JMenu menu = new JMenu("Units");
        ButtonGroup group = new ButtonGroup();
        for (DisplayUnits u : DisplayUnits.values()) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(u.label(), u == initial);
            item.addActionListener(e -> chosen.accept(u));
            group.add(item);
            menu.add(item);
        }
        return menu;
    }

    /** A menu item running {@code action}, with the platform's shortcut modifier and {@code key} (0: none). */
    private static JMenuItem item(String text, int key, Runnable action) {
        JMenuItem item = new JMenuItem(text);
        // Without a display there are no shortcuts to take (the toolkit refuses to name the modifier).
        if (key != 0 && !GraphicsEnvironment.isHeadless()) {
            item.setAccelerator(KeyStroke.getKeyStroke(key, Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx()));
        }
        item.addActionListener(e -> action.run());
        return item;
    }
}
