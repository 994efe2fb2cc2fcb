package rp1.rossum.request;

/** Server side: handles subscription requests read by an {@code RsConnection}. */
public interface RsSubscriptionRequestHandler extends RsRequestHandler {
    void process(RsSubscriptionRequest request);
}
