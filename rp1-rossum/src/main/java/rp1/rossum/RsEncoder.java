package rp1.rossum;

/**
 * A wheel encoder, identified by the part id of the wheel that carries it. Pass encoders to
 * {@code RsClient.sendEncoderStatusRequest}.
 */
public interface RsEncoder {
    /** The id used on the wire: the wheel's part id. */
    int getID();
}
