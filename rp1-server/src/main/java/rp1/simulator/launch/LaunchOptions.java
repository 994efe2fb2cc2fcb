package rp1.simulator.launch;

import java.util.Objects;
import java.util.OptionalInt;

import rp1.planparser.ParsedPlans;

/**
 * How to launch a server beyond its command line: a port that replaces the properties' one (0 for
 * any free port, which tests use), the view, the class loader its clients' classes and class-path
 * resources come from (a sweep gives each run one of its own), where its floor plan comes from (a
 * sweep's runs in one process share the plans parsed once), and the threads of its short tasks of its
 * own (a sweep keeps them from run to run). Immutable; start from
 * {@link #defaults()}.
 */
public final class LaunchOptions {
    final OptionalInt port;
    final ViewHook view;
    /** Null for the thread's context class loader. */
    final ClassLoader loader;
    /** Null: the server parses its floor plan itself. */
    final ParsedPlans plans;
    /** Where the client starter and the stop run: {@link HelperThreads#newThreads()} unless a sweep keeps threads. */
    final HelperThreads helpers;

    private LaunchOptions(OptionalInt port, ViewHook view, ClassLoader loader, ParsedPlans plans, HelperThreads helpers) {
        this.port = port;
        this.view = view;
        this.loader = loader;
        this.plans = plans;
        this.helpers = helpers;
    }

    /** The properties' port and the standard view. */
    public static LaunchOptions defaults() {
        return new LaunchOptions(OptionalInt.empty(), ViewHook.standard(), null, null, HelperThreads.newThreads());
    }

    /** Listens on {@code port} whatever the properties say; 0 picks a free port. */
    public LaunchOptions withPort(int port) {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in [0, 65535], got " + port);
        }
        return new LaunchOptions(OptionalInt.of(port), view, loader, plans, helpers);
    }

    /** Uses {@code view} when the properties enable the GUI. */
    public LaunchOptions withView(ViewHook view) {
        return new LaunchOptions(port, view, loader, plans, helpers);
    }

    /** Loads the clients' classes (and looks for class-path resources) with {@code loader}. */
    public LaunchOptions withClassLoader(ClassLoader loader) {
        return new LaunchOptions(port, view, loader, plans, helpers);
    }

    /** Takes the floor plan from {@code plans} (a copy of one parsed once for many runs) instead of parsing it. */
    public LaunchOptions withPlans(ParsedPlans plans) {
        return new LaunchOptions(port, view, loader, plans, helpers);
    }

    /** Starts the client starter and the stop on {@code helpers} instead of a new thread each. */
    public LaunchOptions withHelperThreads(HelperThreads helpers) {
        return new LaunchOptions(port, view, loader, plans, Objects.requireNonNull(helpers));
    }
}
