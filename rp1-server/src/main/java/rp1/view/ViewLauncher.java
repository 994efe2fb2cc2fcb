package rp1.view;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Paths;

import javax.swing.SwingUtilities;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;
import rp1.simulator.config.ServerConfig;

/**
 * The one entry point the server uses to show a simulation: the window when {@code enableGUI} is set
 * and a display is available, and picture files when {@code snapshotFileName} is set. Without a
 * display (no {@code DISPLAY}, {@code java.awt.headless=true}, or a display that cannot be opened)
 * it logs one line and the simulation runs on headless.
 */
public final class ViewLauncher {
    private ViewLauncher() {
    }

    /**
     * Sets up the view of {@code simulation} as {@code config} asks.
     *
     * @param simulation   the simulation to show
     * @param config       {@code enableGUI}, {@code frameInterval}, {@code snapshotFileName} and
     *                     {@code snapshotInterval} are used
     * @param log          the server log
     * @param exitCallback run, on a thread of its own, when the user closes the window or chooses
     *                     File → Exit; the view never exits the process itself
     * @return what was set up; close it when the simulation has ended
     */
    public static RunningView start(Simulation simulation, ServerConfig config, RsLogInterface log,
                                    Runnable exitCallback) {
        SimulatorWindow window = null;
        if (config.enableGUI) {
            window = openWindow(simulation, config.frameInterval, log, exitCallback);
        } else {
            log.log("GUI is disabled (in response to configuration option)");
        }
        SnapshotWriter writer = null;
        if (config.snapshotFileName != null) {
            writer = new SnapshotWriter(simulation, Paths.get(config.snapshotFileName), config.snapshotInterval, log);
            log.log("Writing a picture of the world to " + config.snapshotFileName + " at exit"
                    + (config.snapshotInterval > 0.0 ? ", and one every " + config.snapshotInterval
                    + " s of simulated time while the world changes" : ""));
        }
        return new RunningView(window, writer);
    }

    /** Whether windows can be opened in this process. */
    public static boolean displayAvailable() {
        return !GraphicsEnvironment.isHeadless();
    }

    private static SimulatorWindow openWindow(Simulation simulation, double frameInterval, RsLogInterface log,
                                              Runnable exit) {
        if (!displayAvailable()) {
            log.log("GUI not available (no display: DISPLAY is not set or java.awt.headless=true); running headless");
            return null;
        }
        log.log("Starting GUI");
        SimulatorWindow[] window = new SimulatorWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> window[0] = new SimulatorWindow(simulation, frameInterval, exit));
            return window[0];
        } catch (InvocationTargetException e) {
            log.log("GUI not available (" + e.getCause() + "); running headless");
        } catch (AWTError | UnsupportedOperationException | LinkageError e) {
            // The toolkit fails this way when DISPLAY names a display that cannot be opened, or when
            // the Java runtime has no windowing libraries.
            log.log("GUI not available (" + e + "); running headless");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            log.log("GUI not started: interrupted while opening the window; running headless");
        }
        return null;
    }
}
