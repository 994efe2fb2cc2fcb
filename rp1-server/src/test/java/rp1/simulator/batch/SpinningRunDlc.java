package rp1.simulator.batch;

/** A robot whose {@code run()} computes for ever on the thread the server gave it. */
public class SpinningRunDlc extends SleepyDlc {
    @Override
    public void run() {
        SpinningHandlerDlc.spin();
    }
}
