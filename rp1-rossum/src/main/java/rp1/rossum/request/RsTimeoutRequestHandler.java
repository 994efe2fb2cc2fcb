package rp1.rossum.request;

/** Server side: handles timeout requests read by an {@code RsConnection}. */
public interface RsTimeoutRequestHandler extends RsRequestHandler {
    /**
     * Handles one timeout request. Server side: called on the thread that decoded it, or for a
     * directly connected client on the thread that sent it (see {@code RsConnection}).
     *
     * @param timeoutPeriod seconds of simulation time until the timeout event
     * @param timeoutIndex the client's number for the timeout, echoed in the event
     */
    void process(double timeoutPeriod, int timeoutIndex);
}
