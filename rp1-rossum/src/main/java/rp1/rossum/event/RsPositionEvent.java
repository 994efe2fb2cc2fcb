package rp1.rossum.event;

/**
 * The robot's exact pose and current motion, answering a position request. Useful for testing and display; a real robot seldom knows its position this well.
 */
public class RsPositionEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** Body origin, world metres. */
    public final double x;
    /** Body origin, world metres. */
    public final double y;
    /** Heading in radians, normalized to (-pi, pi]. */
    public final double orientation;
    /** Linear velocity of the current or last motion, m/s. */
    public final double velocity;
    /** Turn rate of the current or last motion, rad/s. */
    public final double turnRate;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsPositionEvent(double simTime, double x, double y, double orientation, double velocity, double turnRate) {
        super(EVT_POSITION, simTime);
        this.x = x;
        this.y = y;
        this.orientation = orientation;
        this.velocity = velocity;
        this.turnRate = turnRate;
    }
}
