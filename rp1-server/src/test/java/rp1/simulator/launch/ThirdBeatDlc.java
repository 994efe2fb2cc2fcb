package rp1.simulator.launch;

import java.io.IOException;

import rp1.rossum.RsClient;

/**
 * A loaded client the simulation calls directly (it overrides nothing of the event loop): it places
 * a round robot, beats every 0.1 s, and misbehaves at the third beat as its subclass says.
 */
public abstract class ThirdBeatDlc extends RsClient {
    private final String name;
    private final String placement;

    ThirdBeatDlc(String name, String placement) {
        this.name = name;
        this.placement = placement;
    }

    /** What the heartbeat handler does at the third beat. */
    abstract void thirdBeat();

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(TestServer.roundBody(name));
        addHeartbeatEventHandler(e -> {
            if (e.sequence == 3) {
                thirdBeat();
            }
        });
        sendPlacementRequest(placement);
        sendHeartbeatRequest(0.1);
    }
}
