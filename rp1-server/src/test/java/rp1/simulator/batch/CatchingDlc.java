package rp1.simulator.batch;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Paths;

import rp1.rossum.RsClient;

/**
 * A robot whose timeout handler computes, catching whatever is thrown at it, for as long as the file
 * its parameter {@code param.flag} names is there: a thread that cannot be stopped, until the test
 * takes the file away.
 */
public class CatchingDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(Disc.named("catching", 0.1));
        String flag = getRunParameter("flag");
        addTimeoutEventHandler(e -> {
            while (Files.exists(Paths.get(flag))) {
                try {
                    long until = System.nanoTime() + 10_000_000L;
                    while (System.nanoTime() < until) {
                        Thread.onSpinWait();
                    }
                } catch (Throwable t) {
                    // Caught, stop included: the loop goes on.
                }
            }
        });
        sendPlacementRequest("home");
        sendTimeoutRequest(1.0);
    }
}
