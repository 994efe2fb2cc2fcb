package rp1.simulator.launch;

import java.io.IOException;

/** A {@link TestDlc} whose heartbeat handler throws an {@link Error} at the third beat, which ends the client. */
public class ErrorDlc extends TestDlc {
    @Override
    protected String placement() {
        return "p2";
    }

    @Override
    protected int beatsBeforeLeaving() {
        return 0;
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        addHeartbeatEventHandler(e -> {
            if (e.sequence == 3) {
                throw new AssertionError("the robot's own check failed");
            }
        });
    }
}
