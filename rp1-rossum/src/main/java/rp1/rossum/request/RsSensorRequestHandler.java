package rp1.rossum.request;

/** Server side: handles sensor-status requests read by an {@code RsConnection}. */
public interface RsSensorRequestHandler extends RsRequestHandler {
    void process(RsSensorRequest request);
}
