package rp1.simulator.batch;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsClient;

/**
 * A test robot, a disc placed at "home", that counts its heartbeats (every 0.1 simulated s) and
 * reports them as its result "beats". In the run of seed {@link #HOG_SEED} it also keeps 2 MB more
 * of small objects at every beat, up to {@link #KEPT_MB} MB: more than a sweep's process is given in
 * the test, far less than a process of its own has.
 */
public class HogDlc extends RsClient {
    static final long HOG_SEED = 2;
    static final int KEPT_MB = 96;

    private final List<long[]> kept = new ArrayList<>();
    private int beats;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named(placement(), 0.1));
        addTimeoutEventHandler(e -> beat());
        sendPlacementRequest(placement());
        sendTimeoutRequest(0.1);
    }

    /** Where the robot is placed, which is also its name. */
    String placement() {
        return "home";
    }

    private void beat() {
        beats++;
        reportRunResult("beats", beats);
        if (getRunSeed() == HOG_SEED && kept.size() < KEPT_MB * 16_384) {
            for (int i = 0; i < 32_768; i++) {
                kept.add(new long[6]); // 64 bytes
            }
        }
        sendTimeoutRequest(0.1);
    }
}
