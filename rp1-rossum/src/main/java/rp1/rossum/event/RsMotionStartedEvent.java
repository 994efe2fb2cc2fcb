package rp1.rossum.event;

/**
 * A motion began. The velocities echo the request; the duration is the planned one, already shortened if the simulator predicts a collision.
 */
public class RsMotionStartedEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** M/s, as requested. */
    public final double linearVelocity;
    /** Rad/s, as requested. */
    public final double rotationalVelocity;
    /** Planned duration in seconds (shortened by a predicted collision). */
    public final double duration;
    /** Start pose, world metres. */
    public final double x;
    /** Start pose, world metres. */
    public final double y;
    /** Start heading, radians. */
    public final double orientation;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsMotionStartedEvent(double simTime, double linearVelocity, double rotationalVelocity, double duration, double x, double y, double orientation) {
        super(EVT_MOTION_STARTED, simTime);
        this.linearVelocity = linearVelocity;
        this.rotationalVelocity = rotationalVelocity;
        this.duration = duration;
        this.x = x;
        this.y = y;
        this.orientation = orientation;
    }
}
