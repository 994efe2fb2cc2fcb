package rp1.view;

import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.util.function.Consumer;

import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;

/**
 * The window's menus: those of RP1 0.60 (File → Exit, View → Units, Actions → Remove Paint Trails)
 * plus View → Zoom In, Zoom Out and Fit.
 */
final class Menus {
    private Menus() {
    }

    /**
     * @param units        the units checked at first
     * @param unitsChosen  told when the user picks other units
     * @param canvas       zoomed by the View menu
     * @param removeTrails run by Actions → Remove Paint Trails
     * @param exit         run by File → Exit
     */
    static JMenuBar build(DisplayUnits units, Consumer<DisplayUnits> unitsChosen, PlanCanvas canvas,
                          Runnable removeTrails, Runnable exit) {
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
        actions.add(item("Remove Paint Trails", 0, removeTrails));
        bar.add(file);
        bar.add(view);
        bar.add(actions);
        return bar;
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
        if (key != 0) {
            item.setAccelerator(KeyStroke.getKeyStroke(key, Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx()));
        }
        item.addActionListener(e -> action.run());
        return item;
    }
}
