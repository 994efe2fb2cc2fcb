package rp1.rossum.request;

/** Server side: handles placement requests read by an {@code RsConnection}. */
public interface RsPlacementRequestHandler extends RsRequestHandler {
    void process(RsPlacementRequest request);
}
