package rp1.simulator.launch;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;
import rp1.simulator.config.ServerConfig;
import rp1.view.ViewLauncher;
import rp1.web.LiveView;

/**
 * Where a view plugs into the server: called once at start-up (the view itself decides, from
 * {@code enableGUI}, the display and {@code snapshotFileName}, whether to show a window or write
 * pictures). The view
 * observes the simulation (its world's listeners, mouse clicks, "remove paint trails") and never
 * drives it otherwise; the simulation does not know it exists.
 */
@FunctionalInterface
public interface ViewHook {
    /**
     * Opens the view.
     *
     * @return what to close when the server stops
     * @throws Exception if the view cannot be shown; the server then stops with a log line
     */
    AutoCloseable open(Context context) throws Exception;

    /** What a view gets to work with. */
    final class Context {
        /** The simulation to show; its world's listeners say when the picture changes. */
        public final Simulation simulation;
        /** The server's settings (frame rates, snapshot file, ...). */
        public final ServerConfig config;
        /** The server's log. */
        public final RsLogInterface log;
        /** Stops the server as asked (the view's File / Exit and window close): status 0 unless the run failed. */
        public final Runnable exit;

        /** What the server hands to its view. */
        public Context(Simulation simulation, ServerConfig config, RsLogInterface log, Runnable exit) {
            this.simulation = simulation;
            this.config = config;
            this.log = log;
            this.exit = exit;
        }
    }

    /** No view at all (no window, no pictures), for tests of the server itself. */
    ViewHook HEADLESS = context -> {
        context.log.log("GUI is disabled (no view in this server)");
        return () -> { };
    };

    /**
     * The simulator's view ({@link rp1.view.ViewLauncher}): a window, picture files, or neither; and
     * the page a browser watches the run on ({@link rp1.web.LiveView}) if {@code viewPort} asks for it.
     */
    static ViewHook standard() {
        return context -> {
            AutoCloseable live = LiveView.startIfAsked(context.simulation, context.config, context.log);
            AutoCloseable view;
            try {
                view = ViewLauncher.start(context.simulation, context.config, context.log, context.exit);
            } catch (Exception | Error e) {
                live.close();
                throw e;
            }
            return () -> {
                try (live) {
                    view.close();
                }
            };
        };
    }
}
