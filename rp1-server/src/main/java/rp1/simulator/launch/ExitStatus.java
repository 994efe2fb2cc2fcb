package rp1.simulator.launch;

/** The server's exit statuses. */
public final class ExitStatus {
    /** Stopped as asked (Ctrl-C, maxSimulationTime, every loaded client done, the view closed). */
    public static final int OK = 0;
    /** Did not start: bad command line, properties or floor plan, port in use, a view that cannot open. */
    public static final int STARTUP_FAILED = 1;
    /**
     * A loaded client failed: its class could not be loaded, its constructor, initialize() or run()
     * threw, or a handler the simulation called directly threw an Error (whatever then ended the run).
     */
    public static final int CLIENT_FAILED = 2;
    /**
     * The run went as asked, but what it was to leave on disk is not whole: the recording, the event
     * log or a picture could not be written (a full disk, a file that cannot be renamed). The message
     * names the file; nothing half-written is left under a file's own name.
     */
    public static final int OUTPUT_FAILED = 4;
    /**
     * The simulator failed (70 is sysexits' EX_SOFTWARE, an internal error): an {@code Error} (running
     * out of memory, say) ended a thread of the server, which cannot then be trusted to serve anyone
     * (a server of its own ends rather than keep the port open; in a sweep the run stops and the
     * others go on), or a task of the simulation threw (the run went on, its results not to be trusted).
     */
    public static final int FATAL_ERROR = 70;

    private ExitStatus() {
    }
}
