package rp1.rossum.wire;

/** Closing what a connection held, once it has failed or is being abandoned. */
public final class Closing {
    private Closing() {
    }

    /**
     * Closes {@code c} (nothing for null) and ignores a failure to close: the connection is over
     * either way, and a socket or stream that already failed has nothing new to say.
     *
     * @param c the socket, channel, stream or selector to close
     */
    public static void closeQuietly(AutoCloseable c) {
        if (c == null) {
            return;
        }
        try {
            c.close();
        } catch (Exception ignored) {
            // See above.
        }
    }
}
