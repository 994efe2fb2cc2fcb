package rp1.rossum;

/** Thrown when a list of points does not describe a usable polygon (too few points, no area). */
public class RsPolygonException extends Exception {
    private static final long serialVersionUID = 1L;

    public RsPolygonException() {
    }

    public RsPolygonException(String message) {
        super(message);
    }
}
