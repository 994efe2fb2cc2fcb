package rp1.rossum.event;

/**
 * A target's selection state, answering a target-selection request: only selected targets are visible to target sensors.
 */
public class RsTargetSelectionEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** The target's name. */
    public final String targetName;
    /** True if the target is now selected. */
    public final boolean status;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsTargetSelectionEvent(double simTime, String targetName, boolean status) {
        super(EVT_TARGET_SELECTION, simTime);
        this.targetName = targetName;
        this.status = status;
    }
}
