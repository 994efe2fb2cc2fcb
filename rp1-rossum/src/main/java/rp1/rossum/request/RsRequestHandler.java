package rp1.rossum.request;

/**
 * Server side: receives requests decoded by an {@code RsConnection}. Each request type has its own
 * sub-interface adding a typed {@code process} method; implementations provide both.
 */
public interface RsRequestHandler {
    /** Handles any request (the typed {@code process} methods are the ones a connection calls). */
    void processRequest(RsRequest request);
}
