package rp1.rossum;

/** Thrown when a list of points does not describe a usable polygon (too few points, no area). */
public class RsPolygonException extends Exception {
    private static final long serialVersionUID = 1L;

    /** An exception without a message. */
    public RsPolygonException() {
    }

    /**
     * An exception saying what was wrong.
     *
     * @param message the detail message
     */
    public RsPolygonException(String message) {
        super(message);
    }
}
