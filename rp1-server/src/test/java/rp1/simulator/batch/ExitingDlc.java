package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;
import rp1.rossum.event.RsTimeoutEvent;

/** A robot that ends the Java process it runs in one simulated second after it is placed. */
public class ExitingDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("exiting", 0.1));
        addTimeoutEventHandler(this::quit);
        sendPlacementRequest("home");
        sendTimeoutRequest(1.0);
    }

    private void quit(RsTimeoutEvent e) {
        System.exit(3);
    }
}
