package rp1.rossum.request;

/** Report the state of some wheel encoders, optionally clearing their accumulators afterwards. */
public class RsEncoderStatusRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Echoed in every resulting event, so a client can match answers to requests. */
    public final int requestIndex;
    /** Part ids of the wheels whose encoders to report, in reporting order. */
    public final int[] encoderID;
    /** Whether to zero the accumulators after reporting. */
    public final boolean clearOnReport;

    /** A request with these values (the fields say what each one is). */
    public RsEncoderStatusRequest(int requestIndex, int[] encoderID, boolean clearOnReport) {
        super(REQ_ENCODER_STATUS);
        this.requestIndex = requestIndex;
        this.encoderID = encoderID;
        this.clearOnReport = clearOnReport;
    }

    /**
     * The part ids of the wheels to report.
     *
     * @return {@link #encoderID} (the array itself, not a copy)
     */
    public int[] getEncoderID() {
        return encoderID;
    }
}
