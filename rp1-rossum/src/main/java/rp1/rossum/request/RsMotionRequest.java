package rp1.rossum.request;

/**
 * Move with a constant linear and rotational velocity for a while: a straight line, an arc, or a
 * pivot in place. Build one directly or with a wheel system's {@code getMotionRequest...} helpers,
 * and send it with {@code RsClient.sendMotionRequest}.
 */
public class RsMotionRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Seconds. */
    public final double duration;
    /** Metres per second, positive forward. */
    public final double linearVelocity;
    /** Radians per second, positive counter-clockwise (left). */
    public final double rotationalVelocity;

    /** A request with these values (the fields say what each one is). */
    public RsMotionRequest(double linearVelocity, double rotationalVelocity, double duration) {
        super(REQ_MOTION);
        this.linearVelocity = linearVelocity;
        this.rotationalVelocity = rotationalVelocity;
        this.duration = duration;
    }

    @Override
    public String toString() {
        return "RsMotionRequest[v=" + linearVelocity + ", w=" + rotationalVelocity + ", T=" + duration + "]";
    }
}
