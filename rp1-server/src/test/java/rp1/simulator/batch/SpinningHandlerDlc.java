package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;

/** A robot whose timeout handler, called by the simulation itself, computes for ever once it is placed. */
public class SpinningHandlerDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("spinning", 0.1));
        addTimeoutEventHandler(e -> spin());
        sendPlacementRequest("home");
        sendTimeoutRequest(1.0);
    }

    static long spin() {
        long n = 0;
        while (n >= 0) {
            n = (n + 1) & Long.MAX_VALUE;
        }
        return n;
    }
}
