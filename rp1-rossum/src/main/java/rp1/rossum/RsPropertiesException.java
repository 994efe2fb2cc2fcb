package rp1.rossum;

import java.io.IOException;

/** A properties file or command-line option is missing, unreadable or has an invalid value. */
public class RsPropertiesException extends IOException {
    private static final long serialVersionUID = 1L;

    public RsPropertiesException() {
    }

    public RsPropertiesException(String message) {
        super(message);
    }
}
