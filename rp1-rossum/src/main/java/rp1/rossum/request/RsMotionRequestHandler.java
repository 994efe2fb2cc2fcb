package rp1.rossum.request;

/** Server side: handles motion requests read by an {@code RsConnection}. */
public interface RsMotionRequestHandler extends RsRequestHandler {
    void process(RsMotionRequest request);
}
