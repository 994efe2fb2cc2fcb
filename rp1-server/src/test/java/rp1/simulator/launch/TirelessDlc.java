package rp1.simulator.launch;

/** A {@link TestDlc} that never leaves: only the server can end its run. */
public class TirelessDlc extends TestDlc {
    @Override
    protected int beatsBeforeLeaving() {
        return 0;
    }
}
