package rp1.simulator.batch;

/** A sweep cannot start: its properties, plans or output folder are unusable. The message says which and why. */
public class SweepException extends Exception {
    private static final long serialVersionUID = 1L;

    public SweepException(String message) {
        super(message);
    }
}
