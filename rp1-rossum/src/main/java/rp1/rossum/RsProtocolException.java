package rp1.rossum;

import java.io.IOException;

/**
 * A peer broke the RP1 wire protocol: a wrong version, client id or key, an unknown transaction,
 * request, event or part code, a count out of its sane range, malformed text, or a stream that ended
 * in the middle of a message. The message names the field and the value seen. Receiving one ends the
 * session: the reader shuts the connection down.
 */
public class RsProtocolException extends IOException {
    private static final long serialVersionUID = 1L;

    private final String field;

    /** A violation in {@code field}; {@code problem} says what was wrong with it. */
    public RsProtocolException(String field, String problem) {
        super(field + ": " + problem);
        this.field = field;
    }

    /** The name of the field being read when the violation was found. */
    public String getField() {
        return field;
    }
}
