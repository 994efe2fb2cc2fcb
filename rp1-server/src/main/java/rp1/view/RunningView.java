package rp1.view;

import java.io.IOException;

import javax.swing.SwingUtilities;

/**
 * What {@link ViewLauncher#start} set up: the window (if one could be opened) and the picture writer
 * (if picture files were asked for). Closing it closes the window and writes the picture at exit.
 */
public final class RunningView implements AutoCloseable {
    private final SimulatorWindow window;
    private final SnapshotWriter writer;

    RunningView(SimulatorWindow window, SnapshotWriter writer) {
        this.window = window;
        this.writer = writer;
    }

    /** Whether a window is showing the simulation. */
    public boolean hasWindow() {
        return window != null;
    }

    /** Whether pictures are being written. */
    public boolean writesPictures() {
        return writer != null;
    }

    /** The window, for tests in this package; null if there is none. */
    SimulatorWindow window() {
        return window;
    }

    /**
     * Closes the window (without waiting for the event thread, which may be the caller's caller) and
     * writes the picture at exit, waiting until the picture files are written. Call after the
     * simulation has stopped, so the last picture shows where everything ended.
     *
     * @throws IOException if a picture could not be written
     */
    @Override
    public void close() throws IOException {
        if (window != null) {
            SwingUtilities.invokeLater(window::close);
        }
        if (writer != null) {
            writer.close();
        }
    }
}
