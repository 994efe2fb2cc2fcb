package rp1.simulator.launch;

/**
 * The server cannot start; the message says why in one line (file, key and value for configuration
 * errors, FILE:LINE:COLUMN for floor-plan errors) and nothing was left running.
 */
public final class StartupException extends Exception {
    private static final long serialVersionUID = 1L;

    private final int exitStatus;

    /** A failure to start, ending the process with {@code exitStatus}. */
    public StartupException(String message, int exitStatus) {
        super(message);
        this.exitStatus = exitStatus;
    }

    /** A failure to start, with {@link ExitStatus#STARTUP_FAILED}. */
    public StartupException(String message) {
        this(message, ExitStatus.STARTUP_FAILED);
    }

    /** The status the process should exit with ({@link ExitStatus}). */
    public int getExitStatus() {
        return exitStatus;
    }
}
