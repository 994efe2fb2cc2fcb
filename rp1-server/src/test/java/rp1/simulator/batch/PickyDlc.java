package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * A loaded client for sweeps: asks to be placed at "home" and, once it is, ends its session; on a
 * floor plan without "home" its handler fails, which fails the client.
 */
public class PickyDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("picky", 0.15));
        addPlacementEventHandler(e -> {
            if (!e.valid) {
                throw new Error("no placement \"home\" on this floor plan");
            }
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
