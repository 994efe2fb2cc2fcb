package rp1.web;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * A {@link Wanderer} whose {@code initialize()} waits (at most 8 s) until the test opens its gate: a
 * lockstep run's clock starts only once it returns, so the test can connect browsers first.
 */
public class GatedWanderer extends Wanderer {
    private static volatile CountDownLatch gate = new CountDownLatch(0);

    static void close() {
        gate = new CountDownLatch(1);
    }

    static void open() {
        gate.countDown();
    }

    @Override
    public void initialize() throws IOException {
        try {
            gate.await(8, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        super.initialize();
    }
}
