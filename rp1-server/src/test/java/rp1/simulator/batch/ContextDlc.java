package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;

/**
 * A loaded robot that reports whether its own thread's context class loader is the one its class
 * came from (its run's, whether the runs share the robot's classes or not), and leaves.
 */
public class ContextDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        boolean own = Thread.currentThread().getContextClassLoader() == ContextDlc.class.getClassLoader();
        RsBody body = new RsBody("Context");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            reportRunResult("own_context", own ? 1 : 0);
            shutdown();
        });
        sendPlacementRequest("home");
    }
}
