package rp1.rossum.request;

/**
 * Send the floor plan (answered by a plan event). Clients send it with {@code RsClient.sendPlanRequest}
 * to learn the walls, targets, placements and navigation network of the world they are in.
 */
public class RsPlanRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** A plan request; it has no values. */
    public RsPlanRequest() {
        super(REQ_PLAN);
    }
}
