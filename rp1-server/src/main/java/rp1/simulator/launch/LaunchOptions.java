package rp1.simulator.launch;

import java.util.OptionalInt;

/**
 * How to launch a server beyond its command line: a port that replaces the properties' one (0 for
 * any free port, which tests use) and the view. Immutable; start from {@link #defaults()}.
 */
public final class LaunchOptions {
    final OptionalInt port;
    final ViewHook view;

    private LaunchOptions(OptionalInt port, ViewHook view) {
        this.port = port;
        this.view = view;
    }

    /** The properties' port and the standard view. */
    public static LaunchOptions defaults() {
        return new LaunchOptions(OptionalInt.empty(), ViewHook.standard());
    }

    /** Listens on {@code port} whatever the properties say; 0 picks a free port. */
    public LaunchOptions withPort(int port) {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in [0, 65535], got " + port);
        }
        return new LaunchOptions(OptionalInt.of(port), view);
    }

    /** Uses {@code view} when the properties enable the GUI. */
    public LaunchOptions withView(ViewHook view) {
        return new LaunchOptions(port, view);
    }
}
