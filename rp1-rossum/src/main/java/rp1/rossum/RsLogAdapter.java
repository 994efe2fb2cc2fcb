package rp1.rossum;

/**
 * A base for loggers that only need to say where a line goes: {@link #log} and {@link #verbose}
 * become {@link #logIt} with the levels "s" and "v" (verbose lines only while verbosity is on).
 * Handy for tests and for embedding the simulator, e.g. a logger that collects lines in memory.
 */
public abstract class RsLogAdapter implements RsLogInterface {
    private volatile boolean verbosity;

    /** A logger that starts with verbose lines switched off. */
    protected RsLogAdapter() {
    }

    /** A logger with the given verbosity. */
    protected RsLogAdapter(boolean verbosity) {
        this.verbosity = verbosity;
    }

    @Override
    public void log(String message) {
        LogLevels.standard(this, message);
    }

    @Override
    public void verbose(String message) {
        LogLevels.verbose(this, verbosity, message);
    }

    @Override
    public boolean getVerbosity() {
        return verbosity;
    }

    @Override
    public void setVerbosity(boolean value) {
        verbosity = value;
    }
}
