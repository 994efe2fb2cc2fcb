package rp1.rossum.request;

/** Server side: handles target-selection requests read by an {@code RsConnection}. */
public interface RsTargetSelectionRequestHandler extends RsRequestHandler {
    void process(RsTargetSelectionRequest request);
}
