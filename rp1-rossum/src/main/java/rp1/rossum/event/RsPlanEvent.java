package rp1.rossum.event;

/**
 * The floor plan, answering a plan request. {@code plan} is an {@link rp1.rossum.RsPlan} (or null if the server has none) typed {@code Object} for compatibility; cast it.
 */
public class RsPlanEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** The floor plan, an {@code RsPlan}, or null. */
    public final Object plan;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsPlanEvent(double simTime, Object plan) {
        super(EVT_PLAN, simTime);
        this.plan = plan;
    }
}
