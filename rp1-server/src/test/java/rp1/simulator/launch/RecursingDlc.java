package rp1.simulator.launch;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * A loaded client the simulation calls directly (it overrides nothing of the event loop) whose
 * heartbeat handler, at the third beat, recurses without end (a robot's bug) or, if asked, throws an
 * OutOfMemoryError.
 */
public class RecursingDlc extends RsClient {
    /** Whether the third beat runs out of memory instead of stack. */
    static volatile boolean outOfMemory;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(TestServer.roundBody("recursing"));
        addHeartbeatEventHandler(e -> {
            if (e.sequence == 3) {
                if (outOfMemory) {
                    throw new OutOfMemoryError("made up by the test");
                }
                deeper(0);
            }
        });
        sendPlacementRequest("p2");
        sendHeartbeatRequest(0.1);
    }

    private static int deeper(int n) {
        return deeper(n + 1) + 1;
    }
}
