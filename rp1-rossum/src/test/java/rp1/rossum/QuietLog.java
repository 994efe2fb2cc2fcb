package rp1.rossum;

/**
 * A client log that swallows everything. Tests give it to clients whose sessions they end on purpose:
 * a client without a log writes its termination notice to standard error, which would bury the test
 * output under hundreds of "the server closed the connection" lines.
 */
public final class QuietLog extends RsLogAdapter {
    public static final QuietLog INSTANCE = new QuietLog();

    private QuietLog() {
    }

    @Override
    public void logIt(String level, String message) {
    }
}
