package rp1.rossum.request;

/** Server side: handles heartbeat requests read by an {@code RsConnection}. */
public interface RsHeartbeatRequestHandler extends RsRequestHandler {
    void process(RsHeartbeatRequest request);
}
