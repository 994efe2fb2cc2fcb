package rp1.rossum;

/**
 * The bytes ended in the middle of a message. On a stream that is a protocol violation like any other
 * (the peer hung up mid-message); to a connection fed by a non-blocking transport it only means the
 * rest has not arrived yet.
 */
final class TruncatedMessageException extends RsProtocolException {
    private static final long serialVersionUID = 1L;

    TruncatedMessageException(String field) {
        super(field, "stream ended in the middle of a message");
    }
}
