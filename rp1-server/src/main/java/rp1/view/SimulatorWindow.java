package rp1.view;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;

import javax.swing.JFrame;
import javax.swing.Timer;
import javax.swing.WindowConstants;

import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.snapshot.SnapshotPublisher;

/**
 * The simulator's window (behavior.md section 10): the plan canvas, the status panel and the menus.
 * An animation timer polls the latest snapshot and the clock at the animation frame rate; the
 * simulation never waits for the window. It opens as wide as the status line needs on the plan.
 * Closing the window or File → Exit runs the exit callback on a thread of its own (the server decides
 * how to shut down). Create and use on the event thread.
 */
final class SimulatorWindow {
    /** The title of a window whose plan has no caption. */
    static final String UNTITLED = "Rossum's Playhouse -- Untitled Plan";
    /** RP1 0.60's window size, kept as the least a new window gets. */
    static final int MIN_DEFAULT_WIDTH = 500;
    private static final int DEFAULT_HEIGHT = 400;

    private final JFrame frame;
    private final PlanCanvas canvas;
    private final StatusPanel status;
    private final SnapshotPublisher publisher;
    private final Animation animation;
    private final Timer timer;

    /**
     * Builds and shows the window.
     *
     * @param simulation    the simulation shown
     * @param frameInterval seconds of wall time between animation frames
     * @param exit          run (on its own thread) when the user closes the window or chooses Exit
     */
    SimulatorWindow(Simulation simulation, double frameInterval, Runnable exit) {
        RsPlan plan = simulation.getWorld().getPlan();
        // The frame first: if the toolkit fails, it fails here, before the simulation is observed.
        frame = new JFrame(title(plan));
        publisher = new SnapshotPublisher(simulation);
        DisplayUnits units = DisplayUnits.of(plan.getUnits());
        status = new StatusPanel(units);
        status.showPausedBy(simulation::isPaused);
        canvas = new PlanCanvas(new Renderer(plan), publisher.poll(), simulation, status::showPointer);
        animation = new Animation(publisher, simulation::getSimTime, canvas, status);
        animation.frame();
        Runnable exitOnItsThread = () -> new Thread(exit, "rp1-view-exit").start();
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                exitOnItsThread.run();
            }
        });
        frame.setJMenuBar(Menus.build(units, status::setUnits, canvas, simulation, exitOnItsThread));
        frame.getContentPane().setBackground(Color.lightGray);
        frame.getContentPane().add(canvas, BorderLayout.CENTER);
        frame.getContentPane().add(status, BorderLayout.SOUTH);
        frame.pack();
        frame.setSize(defaultWidth(status.widthFor(StatusText.samples(plan, units.units())), frame.getInsets(),
                usableScreenWidth()), DEFAULT_HEIGHT);
        timer = new Timer((int) Math.max(1, Math.round(frameInterval * 1000.0)), e -> animation.frame());
        timer.start();
        frame.setVisible(true);
    }

    /** The title: the plan's caption, or the original's text for an untitled plan. */
    static String title(RsPlan plan) {
        String caption = plan.getCaption();
        return caption == null || caption.isEmpty() ? UNTITLED : caption;
    }

    /**
     * The width a new window opens with: RP1 0.60's {@value #MIN_DEFAULT_WIDTH} pixels, or as wide as
     * the status line needs inside the frame's borders, but no wider than the screen.
     *
     * @param statusWidth the status line's width for the longest line expected on this plan
     * @param frameInsets the frame's borders
     * @param screenWidth the usable width of the screen
     */
    static int defaultWidth(int statusWidth, Insets frameInsets, int screenWidth) {
        int fitting = statusWidth + frameInsets.left + frameInsets.right;
        return Math.max(MIN_DEFAULT_WIDTH, Math.min(fitting, screenWidth));
    }

    private static int usableScreenWidth() {
        return GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds().width;
    }

    JFrame frame() {
        return frame;
    }

    PlanCanvas canvas() {
        return canvas;
    }

    StatusPanel status() {
        return status;
    }

    /** Stops the animation, stops observing the simulation and closes the window. */
    void close() {
        timer.stop();
        publisher.close();
        frame.dispose();
    }
}
