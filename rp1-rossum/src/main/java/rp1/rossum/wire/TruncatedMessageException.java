package rp1.rossum.wire;

import rp1.rossum.RsProtocolException;

/**
 * The bytes ended in the middle of a message. On a stream that is a protocol violation like any other
 * (the peer hung up mid-message); to a connection fed by a non-blocking transport it only means the
 * rest has not arrived yet.
 */
public final class TruncatedMessageException extends RsProtocolException {
    private static final long serialVersionUID = 1L;

    /** The bytes ended while {@code field} was being read. */
    public TruncatedMessageException(String field) {
        super(field, "stream ended in the middle of a message");
    }
}
