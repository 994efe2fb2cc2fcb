package rp1.simulator.batch;

import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;
import rp1.rossum.RsProperties;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * A loaded robot for experiments: placed where {@code param.place} says (home by default), it drives
 * straight ahead at {@code param.speed} m/s for two seconds, reports its speed, the run's seed and how
 * many of its kind this class has made, and ends its session.
 */
public class ExperimentDlc extends RsClient {
    /** Counts the instances of this class: 1 in every run when each run has its own classes. */
    private static int made;

    /** The same robot as a program of its own, connecting where a sweep's {@code --client} says (RP1_HOST, RP1_PORT). */
    public static void main(String[] args) throws IOException {
        RsProperties p = new RsProperties();
        p.hostName = System.getenv("RP1_HOST");
        p.port = Integer.parseInt(System.getenv("RP1_PORT"));
        ExperimentDlc robot = new ExperimentDlc();
        robot.initialize(p);
        robot.run();
        // A program that fails after its robot has left (RP1_PARAM_exit: its exit status).
        String exit = System.getenv("RP1_PARAM_exit");
        if (exit != null) {
            System.exit(Integer.parseInt(exit));
        }
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        made++;
        double speed = Double.parseDouble(orElse(getRunParameter("speed"), "0.2"));
        RsBody body = new RsBody("Experimenter");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            if (e.valid) {
                sendMotionRequest(new RsMotionRequest(speed, 0.0, 2.0));
            }
        });
        addMotionHaltedEventHandler((RsMotionHaltedEvent e) -> {
            reportRunResult("speed", speed);
            reportRunResult("seed", getRunSeed());
            reportRunResult("made", made);
            shutdown();
        });
        sendPlacementRequest(orElse(getRunParameter("place"), "home"));
    }

    private static String orElse(String v, String fallback) {
        return v == null ? fallback : v;
    }
}
