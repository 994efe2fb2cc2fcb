package rp1.simulator.batch;

import java.nio.file.Files;
import java.nio.file.Paths;

/**
 * A robot whose timeout handler computes, catching whatever is thrown at it, for as long as the file
 * its parameter {@code param.flag} names is there: a thread that cannot be stopped, until the test
 * takes the file away.
 */
public class CatchingDlc extends OneSecondDlc {
    public CatchingDlc() {
        super("catching");
    }

    @Override
    void atOneSecond() {
        String flag = getRunParameter("flag");
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
    }
}
