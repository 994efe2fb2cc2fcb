package rp1demo.clientzero;

import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;

/**
 * Every timeout of the client comes here, whoever asked for it; the index tells them apart. The
 * back-off after a collision is ClientZero's.
 */
public class ClnTimeoutEventHandler implements RsTimeoutEventHandler {
    private final ClnMain client;

    public ClnTimeoutEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsTimeoutEvent event) {
        if (client.backOffIfDue(event.timeoutIndex)) {
            client.log("Backing away from the wall");
        }
    }
}
