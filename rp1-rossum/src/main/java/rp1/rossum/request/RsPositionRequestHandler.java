package rp1.rossum.request;

/** Server side: handles position requests read by an {@code RsConnection}. */
public interface RsPositionRequestHandler extends RsRequestHandler {
    void process();
}
