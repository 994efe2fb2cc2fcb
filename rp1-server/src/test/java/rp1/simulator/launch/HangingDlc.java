package rp1.simulator.launch;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;

import rp1.rossum.RsClient;

/** A loaded client, called directly, whose heartbeat handler never returns at the third beat (until the test lets it). */
public class HangingDlc extends RsClient {
    /** Lets the handler return, once the test is done with the server. */
    static volatile CountDownLatch release = new CountDownLatch(1);

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(TestServer.roundBody("hanging"));
        addHeartbeatEventHandler(e -> {
            if (e.sequence == 3) {
                try {
                    release.await();
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                }
            }
        });
        sendPlacementRequest("p1");
        sendHeartbeatRequest(0.1);
    }
}
