package rp1.rossum.request;

/** Server side: handles halt requests read by an {@code RsConnection}. */
public interface RsHaltRequestHandler extends RsRequestHandler {
    void process(RsHaltRequest request);
}
