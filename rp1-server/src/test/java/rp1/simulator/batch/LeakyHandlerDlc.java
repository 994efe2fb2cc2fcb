package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * A robot that starts a thread of its own from a handler once it is placed (so on the simulation's
 * thread), deaf to interrupts and never ending, then leaves: like {@link LeakyDlc}'s, what it leaves
 * behind must not run on through the later runs of a sweep's process.
 */
public class LeakyHandlerDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("leaky", 0.1));
        addPlacementEventHandler(e -> {
            Thread helper = new Thread(LeakyDlc::spin, "leaky handler's helper");
            helper.setDaemon(true);
            helper.start();
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
