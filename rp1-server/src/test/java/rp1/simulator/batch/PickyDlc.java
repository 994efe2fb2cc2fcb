package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;

/**
 * A loaded client for sweeps: asks to be placed at "home" and, once it is, ends its session; on a
 * floor plan without "home" its handler fails, which fails the client.
 */
public class PickyDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = new RsBody("picky");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            if (!e.valid) {
                throw new Error("no placement \"home\" on this floor plan");
            }
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
