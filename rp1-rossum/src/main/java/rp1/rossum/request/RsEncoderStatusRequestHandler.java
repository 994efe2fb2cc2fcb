package rp1.rossum.request;

/** Server side: handles encoder-status requests read by an {@code RsConnection}. */
public interface RsEncoderStatusRequestHandler extends RsRequestHandler {
    void process(RsEncoderStatusRequest request);
}
