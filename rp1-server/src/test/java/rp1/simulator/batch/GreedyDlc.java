package rp1.simulator.batch;

/**
 * A robot whose timeout handler runs out of memory (thrown as the JVM would throw it, without filling
 * the tests' heap).
 */
public class GreedyDlc extends OneSecondDlc {
    public GreedyDlc() {
        super("greedy");
    }

    @Override
    void atOneSecond() {
        throw new OutOfMemoryError("Java heap space");
    }
}
