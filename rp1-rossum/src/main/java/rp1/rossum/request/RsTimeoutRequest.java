package rp1.rossum.request;

/**
 * Send a timeout event after a duration of simulation time. Clients send it with
 * {@code RsClient.sendTimeoutRequest} to be woken up later, e.g. to end a manoeuvre.
 */
public class RsTimeoutRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Seconds of simulation time; negative values are stored as 0. */
    public final double timeoutDuration;
    /** Echoed in the timeout event. */
    public final int timeoutIndex;

    /** A request with these values (the fields say what each one is). */
    public RsTimeoutRequest(double timeoutDuration, int timeoutIndex) {
        super(REQ_TIMEOUT);
        this.timeoutDuration = Math.max(0.0, timeoutDuration);
        this.timeoutIndex = timeoutIndex;
    }
}
