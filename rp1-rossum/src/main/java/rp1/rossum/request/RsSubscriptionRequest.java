package rp1.rossum.request;

/**
 * Start or stop delivery of one kind of simulation-generated event (e.g. one sensor's events). The
 * client library sends these itself when handlers are added and removed.
 */
public class RsSubscriptionRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** The event code ({@code RsEvent.EVT_*}). */
    public final int eventCode;
    /** 0, or the sensor id for sensor events. */
    public final int eventIndex;
    /** True to subscribe, false to unsubscribe. */
    public final boolean eventEnable;

    /** A request with these values (the fields say what each one is). */
    public RsSubscriptionRequest(int eventCode, int eventIndex, boolean eventEnable) {
        super(REQ_SUBSCRIPTION);
        this.eventCode = eventCode;
        this.eventIndex = eventIndex;
        this.eventEnable = eventEnable;
    }
}
