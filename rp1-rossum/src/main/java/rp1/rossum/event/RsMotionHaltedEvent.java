package rp1.rossum.event;

/**
 * A motion ended: it ran to completion, was halted on request (a halt or placement request), or was
 * cut short by a collision. The pose is where the robot stopped.
 */
public class RsMotionHaltedEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** {@link #causeOfHalt}: the motion ran its full duration. */
    public static final int HALTED_ON_COMPLETION = 0;
    /** {@link #causeOfHalt}: a halt request, or a placement, ended it. */
    public static final int HALTED_ON_REQUEST = 1;
    /** {@link #causeOfHalt}: the robot ran into something. */
    public static final int HALTED_ON_COLLISION = 2;

    /** One of the {@code HALTED_ON_*} causes. */
    public final int causeOfHalt;
    /** Stop pose, world metres. */
    public final double x;
    /** Stop pose, world metres. */
    public final double y;
    /** Stop heading, radians. */
    public final double orientation;
    /** How long the motion that ended lasted, seconds. */
    public final double duration;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsMotionHaltedEvent(double simTime, int causeOfHalt, double x, double y, double orientation, double duration) {
        super(EVT_MOTION_HALTED, simTime);
        this.causeOfHalt = causeOfHalt;
        this.x = x;
        this.y = y;
        this.orientation = orientation;
        this.duration = duration;
    }

    /** "completion", "request", "collision", or "internal error" for an unknown cause. */
    public String whyHalted() {
        switch (causeOfHalt) {
            case HALTED_ON_COMPLETION:
                return "completion";
            case HALTED_ON_REQUEST:
                return "request";
            case HALTED_ON_COLLISION:
                return "collision";
            default:
                return "internal error";
        }
    }
}
