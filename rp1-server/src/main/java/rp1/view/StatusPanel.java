package rp1.view;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.FontMetrics;
import java.awt.Insets;
import java.util.List;
import java.util.function.BooleanSupplier;

import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

import rp1.rossum.RsPoint;
import rp1.rossum.RsUnits;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The panel below the canvas: a status line with the simulation time and the robots' poses, and
 * the two read-only fields with the floor coordinates under the pointer (behavior.md section 10),
 * and beside them how to drive a robot with the mouse. Used on the event thread only.
 */
final class StatusPanel extends JPanel {
    private static final long serialVersionUID = 1L;
    private static final int READOUT_COLUMNS = 14;
    /** What the mouse does; a newcomer otherwise finds it only in the guide. */
    static final String CLICK_HINT = "left-click: send the robot there   right-click: turn it that way"
            + "   (robots that ask for clicks)";

    private final JLabel state = new JLabel(" ");
    private final JTextField x = readOnlyField();
    private final JTextField y = readOnlyField();
    private transient RsUnits units;
    private transient WorldSnapshot shown;
    private double shownTime;
    /** Whether the run is paused now (the Run menu), said after the time. */
    private transient BooleanSupplier paused = () -> false;
    private transient RsPoint pointer;

    StatusPanel(DisplayUnits initial) {
        super(new BorderLayout());
        units = initial.units();
        state.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        JPanel readouts = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 2));
        readouts.add(x);
        readouts.add(y);
        JLabel hint = new JLabel(CLICK_HINT);
        hint.setBorder(BorderFactory.createEmptyBorder(0, 6, 2, 6));
        JPanel below = new JPanel(new BorderLayout());
        below.add(readouts, BorderLayout.NORTH);
        below.add(hint, BorderLayout.SOUTH);
        add(state, BorderLayout.NORTH);
        add(below, BorderLayout.SOUTH);
    }

    private static JTextField readOnlyField() {
        JTextField f = new JTextField(READOUT_COLUMNS);
        f.setEditable(false);
        return f;
    }

    /** Shows coordinates in {@code u} from now on. */
    void setUnits(DisplayUnits u) {
        units = u.units();
        refresh();
    }

    /** Where the status line learns whether the run is paused. */
    void showPausedBy(BooleanSupplier source) {
        paused = source;
    }

    /** Shows the simulation time {@code simTime} and the robots' poses in {@code s}. */
    void showState(WorldSnapshot s, double simTime) {
        shown = s;
        shownTime = simTime;
        state.setText(StatusText.describe(simTime, paused.getAsBoolean(), s.robots(), units));
    }

    /** The width, in pixels, the status line needs to show the widest of {@code lines} in full. */
    int widthFor(List<String> lines) {
        FontMetrics metrics = state.getFontMetrics(state.getFont());
        int widest = 0;
        for (String line : lines) {
            widest = Math.max(widest, metrics.stringWidth(line));
        }
        Insets around = state.getInsets();
        return around.left + widest + around.right;
    }

    /** Shows the floor point under the pointer; null clears the fields. */
    void showPointer(RsPoint p) {
        pointer = p;
        x.setText(p == null ? "" : StatusText.readout("x", p.x, units));
        y.setText(p == null ? "" : StatusText.readout("y", p.y, units));
    }

    private void refresh() {
        if (shown != null) {
            showState(shown, shownTime);
        }
        showPointer(pointer);
    }

    /** The status line's text. */
    String stateText() {
        return state.getText();
    }
}
