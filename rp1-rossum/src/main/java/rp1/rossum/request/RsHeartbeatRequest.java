package rp1.rossum.request;

/** Start (or with interval 0, cancel) a periodic heartbeat event. */
public class RsHeartbeatRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Seconds of simulation time between beats; 0 cancels. */
    public final double interval;

    /** A request with these values (the fields say what each one is). */
    public RsHeartbeatRequest(double interval) {
        super(REQ_HEARTBEAT);
        this.interval = interval;
    }
}
