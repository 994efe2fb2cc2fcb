package rp1.rossum.request;

/** Server side: handles actuator-control requests read by an {@code RsConnection}. */
public interface RsActuatorControlRequestHandler extends RsRequestHandler {
    void process(RsActuatorControlRequest request);
}
