package rp1.rossum.event;

/**
 * One beat of a periodic heartbeat requested with {@code sendHeartbeatRequest}: a steady tick in
 * simulation time for clients that poll sensors or re-plan at regular intervals.
 */
public class RsHeartbeatEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** 1 for the first beat after the request, then 2, 3, .... */
    public final int sequence;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsHeartbeatEvent(double simTime, int sequence) {
        super(EVT_HEARTBEAT, simTime);
        this.sequence = sequence;
    }
}
