package rp1.rossum;

/**
 * The two levels every {@link RsLogInterface} writes through {@link RsLogInterface#logIt}: "s" for
 * {@code log}, "v" for {@code verbose} and only while verbosity is on. 0.60's API makes
 * {@link RsLogAdapter}, {@link RsProtocol} and {@link RsLogger} each implement those methods (the
 * latter two keep their verbosity in fields of their own), so they share the meaning here.
 */
final class LogLevels {
    private LogLevels() {
    }

    /** Writes a standard line to {@code log}. */
    static void standard(RsLogInterface log, String message) {
        log.logIt("s", message);
    }

    /** Writes a verbose line to {@code log} if {@code verbosity} is on. */
    static void verbose(RsLogInterface log, boolean verbosity, String message) {
        if (verbosity) {
            log.logIt("v", message);
        }
    }
}
