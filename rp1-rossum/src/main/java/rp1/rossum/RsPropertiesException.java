package rp1.rossum;

import java.io.IOException;

/** A properties file or command-line option is missing, unreadable or has an invalid value. */
public class RsPropertiesException extends IOException {
    private static final long serialVersionUID = 1L;

    /** An exception without a message. */
    public RsPropertiesException() {
    }

    /**
     * An exception saying what was wrong.
     *
     * @param message the detail message
     */
    public RsPropertiesException(String message) {
        super(message);
    }
}
