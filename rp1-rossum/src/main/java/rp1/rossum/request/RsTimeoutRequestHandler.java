package rp1.rossum.request;

/** Server side: handles timeout requests read by an {@code RsConnection}. */
public interface RsTimeoutRequestHandler extends RsRequestHandler {
    void process(double timeoutPeriod, int timeoutIndex);
}
