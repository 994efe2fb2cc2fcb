package rp1.rossum.request;

/** Stop the current motion now (answered by a motion-halted event with cause "request"). */
public class RsHaltRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** A halt request; it has no values. */
    public RsHaltRequest() {
        super(REQ_HALT);
    }
}
