package rp1.rossum.event;

/**
 * The state of one wheel encoder, answering an encoder-status request: counts of encoder interval
 * boundaries crossed, the direction of the last movement, and the wheel's angle.
 */
public class RsEncoderStatusEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** The index {@code sendEncoderStatusRequest} returned. */
    public final int requestIndex;
    /** Part id of the wheel carrying the encoder. */
    public final int encoderID;
    /** Signed count of interval boundaries crossed (backwards counts down). */
    public final int accumulatorValue;
    /** Unsigned count of interval boundaries crossed. */
    public final int absoluteAccumulatorValue;
    /** +1 if the last movement was forward, -1 if backward, 0 if the wheel never moved. */
    public final int quadratureValue;
    /** Current interval number. */
    public final int encoderInterval;
    /** Wheel angle in [0, 2 pi). */
    public final double encoderAngle;
    /** True if the accumulators were cleared after this report. */
    public final boolean clearOnReport;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsEncoderStatusEvent(double simTime, int requestIndex, int encoderID, int accumulatorValue,
                                int absoluteAccumulatorValue, int quadratureValue, int encoderInterval,
                                double encoderAngle, boolean clearOnReport) {
        super(EVT_ENCODER_STATUS, simTime);
        this.requestIndex = requestIndex;
        this.encoderID = encoderID;
        this.accumulatorValue = accumulatorValue;
        this.absoluteAccumulatorValue = absoluteAccumulatorValue;
        this.quadratureValue = quadratureValue;
        this.encoderInterval = encoderInterval;
        this.encoderAngle = encoderAngle;
        this.clearOnReport = clearOnReport;
    }
}
