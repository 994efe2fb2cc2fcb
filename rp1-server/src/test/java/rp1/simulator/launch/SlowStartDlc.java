package rp1.simulator.launch;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;

import rp1.rossum.RsClient;

/**
 * A dynamically loaded client for tests whose {@code initialize()} does not return until its thread is
 * interrupted: the robot before others in {@code dlcName} that keeps them waiting their turn.
 */
public class SlowStartDlc extends RsClient {
    /** Counted down once a SlowStartDlc's initialize() has begun. */
    static volatile CountDownLatch entered = new CountDownLatch(1);

    static void reset() {
        entered = new CountDownLatch(1);
    }

    @Override
    public void initialize() throws IOException {
        entered.countDown();
        try {
            new CountDownLatch(1).await();
        } catch (InterruptedException e) {
            throw new IOException("interrupted while initializing");
        }
    }
}
