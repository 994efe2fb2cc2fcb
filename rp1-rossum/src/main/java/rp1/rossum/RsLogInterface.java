package rp1.rossum;

/**
 * Where log lines go. Levels by convention: "s" standard, "v" verbose (only written when verbosity
 * is on), "X" important. The server's log implements it so a loaded client can write into it.
 */
public interface RsLogInterface {
    /** Writes {@code message} at {@code level}. */
    void logIt(String level, String message);

    /** Writes a standard ("s") line. */
    void log(String message);

    /** Writes a verbose ("v") line if verbosity is on. */
    void verbose(String message);

    /**
     * Whether verbose lines are written.
     *
     * @return the verbosity
     */
    boolean getVerbosity();

    /**
     * Switches verbose lines on or off.
     *
     * @param value whether verbose lines are written
     */
    void setVerbosity(boolean value);
}
