package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsClient;
import rp1.rossum.RsMotion;

/** A 0.60-style robot that numbers its motions with RsMotion.getNewContinuityID() and reports the first number. */
public class NumberingDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("Numbering", 0.15));
        addPlacementEventHandler(e -> {
            reportRunResult("first", RsMotion.getNewContinuityID());
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
