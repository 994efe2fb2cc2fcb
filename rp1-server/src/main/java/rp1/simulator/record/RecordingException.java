package rp1.simulator.record;

/**
 * A recording cannot be replayed: it cannot be read, is damaged (the message names the file and line
 * and what is wrong there), is of another format version, or comes from another version of the world
 * model.
 */
public class RecordingException extends Exception {
    private static final long serialVersionUID = 1L;

    public RecordingException(String message) {
        super(message);
    }

    public RecordingException(String message, Throwable cause) {
        super(message, cause);
    }
}
