package rp1.rossum.event;

/**
 * The answer to a placement request: whether the robot was put on the floor, at which named
 * placement, and where. The orientation is exactly the placement's, not normalized. An invalid
 * placement leaves the robot off the floor and reports a zero pose.
 */
public class RsPlacementEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** The placement's name ("$random" for a random pose, the requested name if invalid). */
    public final String name;
    /** True if the robot is now placed. */
    public final boolean valid;
    /** Placement pose, world metres. */
    public final double x;
    /** Placement pose, world metres. */
    public final double y;
    /** Placement heading, radians, as stored in the plan. */
    public final double orientation;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsPlacementEvent(double simTime, boolean valid, String name, double x, double y, double orientation) {
        super(EVT_PLACEMENT, simTime);
        this.valid = valid;
        this.name = name;
        this.x = x;
        this.y = y;
        this.orientation = orientation;
    }

    /**
     * The placement's name.
     *
     * @return {@link #name}
     */
    public String getName() {
        return name;
    }

    /**
     * Whether the robot is now placed.
     *
     * @return {@link #valid}
     */
    public boolean getValid() {
        return valid;
    }
}
