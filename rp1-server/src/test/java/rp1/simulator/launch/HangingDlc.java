package rp1.simulator.launch;

import java.util.concurrent.CountDownLatch;

/** A loaded client, called directly, whose heartbeat handler never returns at the third beat (until the test lets it). */
public class HangingDlc extends ThirdBeatDlc {
    /** Lets the handler return, once the test is done with the server. */
    static volatile CountDownLatch release = new CountDownLatch(1);

    public HangingDlc() {
        super("hanging", "p1");
    }

    @Override
    void thirdBeat() {
        try {
            release.await();
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
        }
    }
}
