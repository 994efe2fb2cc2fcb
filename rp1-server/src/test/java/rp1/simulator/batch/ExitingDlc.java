package rp1.simulator.batch;

/** A robot that ends the Java process it runs in one simulated second after it is placed. */
public class ExitingDlc extends OneSecondDlc {
    public ExitingDlc() {
        super("exiting");
    }

    @Override
    void atOneSecond() {
        quit();
    }

    private void quit() {
        System.exit(3);
    }
}
