package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * A robot that starts a thread of its own in {@code initialize()}, deaf to interrupts and never
 * ending, then leaves once it is placed: what it leaves behind must not run on through the later runs
 * of a sweep's process.
 */
public class LeakyDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        Thread helper = new Thread(LeakyDlc::spin, "leaky helper");
        helper.setDaemon(true);
        helper.start();
        sendBodySpecification(Disc.named("leaky", 0.1));
        addPlacementEventHandler(e -> shutdown());
        sendPlacementRequest("home");
    }

    /** Sleeps 5 ms at a time for ever, interrupted or not. */
    static void spin() {
        while (true) {
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                // Deaf to interrupts, as a careless loop is.
            }
        }
    }
}
