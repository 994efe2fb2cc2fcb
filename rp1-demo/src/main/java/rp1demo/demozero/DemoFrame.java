package rp1demo.demozero;

import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.lang.reflect.InvocationTargetException;
import java.util.Locale;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;

import rp1demo.clientzero.ClnMain;

/**
 * DemoZero's window: the robot's status and position, what its head sees, the simulation clock,
 * and buttons to send the robot home or halt it. Its {@code show...} methods may be called from any
 * thread: they hand the change to Swing's event thread and return at once, so the client's event
 * loop never waits for the screen. Closing the window leaves the robot and the simulator running.
 */
final class DemoFrame extends JFrame {
    private static final long serialVersionUID = 1L;

    private final JLabel status = new JLabel("Connecting...");
    private final JLabel position = new JLabel(" ");
    private final JLabel head = new JLabel("nothing in sight");
    private final JLabel clock = new JLabel("0.0 s");

    private DemoFrame(ClnMain client) {
        super("DemoZero");
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        JPanel readouts = new JPanel(new GridLayout(0, 2, 8, 4));
        readouts.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        addRow(readouts, "Status", status);
        addRow(readouts, "Position", position);
        addRow(readouts, "Head", head);
        addRow(readouts, "Simulation time", clock);
        JPanel buttons = new JPanel();
        JButton home = new JButton("Home");
        home.addActionListener(e -> client.sendPlacementRequest("home"));
        JButton halt = new JButton("Halt");
        halt.addActionListener(e -> client.sendHaltRequest());
        buttons.add(home);
        buttons.add(halt);
        getContentPane().add(readouts, BorderLayout.CENTER);
        getContentPane().add(buttons, BorderLayout.SOUTH);
        pack();
    }

    private static void addRow(JPanel panel, String name, JLabel value) {
        panel.add(new JLabel(name + ":"));
        panel.add(value);
    }

    /**
     * Creates the window on Swing's event thread and shows it. Called from {@code initialize()},
     * before the event loop runs, so waiting for Swing here holds up no event.
     */
    static DemoFrame open(ClnMain client) {
        DemoFrame[] made = new DemoFrame[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                made[0] = new DemoFrame(client);
                made[0].setVisible(true);
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while opening the DemoZero window", e);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("cannot open the DemoZero window", e.getCause());
        }
        return made[0];
    }

    void showStatus(String text) {
        later(status, text);
    }

    void showPosition(String text) {
        later(position, text);
    }

    void showHead(String text) {
        later(head, text);
    }

    void showClock(double simTime) {
        later(clock, String.format(Locale.ROOT, "%.1f s", simTime));
    }

    void showDisconnected() {
        later(status, "Disconnected from the simulator");
    }

    private static void later(JLabel label, String text) {
        SwingUtilities.invokeLater(() -> label.setText(text));
    }
}
