package rp1.rossum.request;

/**
 * Put the robot on the floor: at the named placement of the floor plan, at a random one of them
 * (null or empty name), or at a random free pose ("$random").
 */
public class RsPlacementRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** The placement's name; null or empty for a random placement, "$random" for a random pose. */
    public final String name;

    /** A request with these values (the fields say what each one is). */
    public RsPlacementRequest(String name) {
        super(REQ_PLACEMENT);
        this.name = name;
    }
}
