package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;
import rp1.rossum.event.RsTimeoutEvent;

/**
 * A robot whose timeout handler runs out of memory (thrown as the JVM would throw it, without filling
 * the tests' heap).
 */
public class GreedyDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("greedy", 0.1));
        addTimeoutEventHandler(this::hoard);
        sendPlacementRequest("home");
        sendTimeoutRequest(1.0);
    }

    private void hoard(RsTimeoutEvent e) {
        throw new OutOfMemoryError("Java heap space");
    }
}
