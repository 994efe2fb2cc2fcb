package rp1.rossum.request;

/** Server side: handles position requests read by an {@code RsConnection}. */
public interface RsPositionRequestHandler extends RsRequestHandler {
    /**
     * Handles one position request (it has no values). Server side: called on the thread that
     * decoded it, or for a directly connected client on the thread that sent it (see {@code
     * RsConnection}).
     */
    void process();
}
