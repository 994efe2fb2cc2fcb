package rp1.rossum.request;

/** Send the floor plan (answered by a plan event). */
public class RsPlanRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    public RsPlanRequest() {
        super(REQ_PLAN);
    }
}
