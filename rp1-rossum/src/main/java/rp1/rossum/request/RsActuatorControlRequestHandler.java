package rp1.rossum.request;

/** Server side: handles actuator-control requests read by an {@code RsConnection}. */
public interface RsActuatorControlRequestHandler extends RsRequestHandler {
    /**
     * Handles one request as the connection decoded it. Server side: called on the thread that
     * decoded it, or for a directly connected client on the thread that sent it (see {@code
     * RsConnection}).
     *
     * @param request the request
     */
    void process(RsActuatorControlRequest request);
}
