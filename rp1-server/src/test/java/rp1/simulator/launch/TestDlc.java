package rp1.simulator.launch;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import rp1.rossum.RsClient;
import rp1.rossum.RsLogInterface;

/**
 * A dynamically loaded client for tests: records the calls the server makes on it, says hello in the
 * log, places its robot at p1 (unless told otherwise), asks for a heartbeat every 0.1 s and, after
 * the fifth beat, ends its session, so that its {@code run()} returns.
 */
public class TestDlc extends RsClient {
    /** Calls on every instance, in order. */
    static final List<String> CALLS = Collections.synchronizedList(new ArrayList<>());
    /** Simulation times of the heartbeats received. */
    static final List<Double> BEATS = Collections.synchronizedList(new ArrayList<>());

    private boolean initializing;

    public TestDlc() {
        CALLS.add("constructor");
    }

    static void reset() {
        CALLS.clear();
        BEATS.clear();
    }

    /** Where the robot asks to be placed. */
    protected String placement() {
        return "p1";
    }

    /** Heartbeats after which the client leaves; 0 for never. */
    protected int beatsBeforeLeaving() {
        return 5;
    }

    @Override
    public void setInputOutputStreams(InputStream in, OutputStream out) {
        if (!initializing) {
            CALLS.add("setInputOutputStreams");
        }
        super.setInputOutputStreams(in, out);
    }

    @Override
    public void setLogger(RsLogInterface logger) {
        if (!initializing) {
            CALLS.add("setLogger");
        }
        super.setLogger(logger);
    }

    @Override
    public void initialize() throws IOException {
        CALLS.add("initialize");
        initializing = true;
        try {
            super.initialize();
        } finally {
            initializing = false;
        }
        log("TestDlc says hello");
        sendBodySpecification(TestServer.roundBody("dlc"));
        addHeartbeatEventHandler(e -> {
            BEATS.add(e.simTime);
            if (e.sequence == beatsBeforeLeaving()) {
                shutdown();
            }
        });
        sendPlacementRequest(placement());
        sendHeartbeatRequest(0.1);
    }

    @Override
    public void run() {
        CALLS.add("run");
        super.run();
    }
}
