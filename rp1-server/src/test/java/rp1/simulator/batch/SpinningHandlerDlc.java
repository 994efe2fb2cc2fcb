package rp1.simulator.batch;

/** A robot whose timeout handler, called by the simulation itself, computes for ever once it is placed. */
public class SpinningHandlerDlc extends OneSecondDlc {
    public SpinningHandlerDlc() {
        super("spinning");
    }

    @Override
    void atOneSecond() {
        spin();
    }

    static long spin() {
        long n = 0;
        while (n >= 0) {
            n = (n + 1) & Long.MAX_VALUE;
        }
        return n;
    }
}
