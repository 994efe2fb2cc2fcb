package rp1.rossum.event;

/**
 * A timeout requested with {@code sendTimeoutRequest} fell due; {@code simTime} is the time it was due.
 */
public class RsTimeoutEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** The index {@code sendTimeoutRequest} returned. */
    public final int timeoutIndex;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsTimeoutEvent(double simTime, int timeoutIndex) {
        super(EVT_TIMEOUT, simTime);
        this.timeoutIndex = timeoutIndex;
    }
}
