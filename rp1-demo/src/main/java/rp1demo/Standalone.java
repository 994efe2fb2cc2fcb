package rp1demo;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * How each demo's {@code main} runs it on its own, against a simulator that is already running: a
 * simulator that cannot be reached is one line on standard error and exit status 1, not a stack
 * trace.
 */
public final class Standalone {
    private Standalone() {
    }

    /** Connects {@code client} (host and port from its rossum.ini) and runs its event loop. */
    public static void run(RsClient client) {
        try {
            client.initialize();
        } catch (IOException e) {
            System.err.println(e.getMessage());
            System.exit(1);
        }
        client.run();
    }
}
