package rp1.rossum.request;

/** Server side: handles plan requests read by an {@code RsConnection}. */
public interface RsPlanRequestHandler extends RsRequestHandler {
    void process(RsPlanRequest request);
}
