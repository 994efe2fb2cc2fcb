package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;
import rp1.rossum.RsMotion;

/** A 0.60-style robot that numbers its motions with RsMotion.getNewContinuityID() and reports the first number. */
public class NumberingDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = new RsBody("Numbering");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            reportRunResult("first", RsMotion.getNewContinuityID());
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
