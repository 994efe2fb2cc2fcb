package rp1.rossum;

/**
 * Server side: receives the robot body a client specified, so that the simulator can put the robot
 * into its world. The simulator registers one with {@link RsConnection#setBodyHandler}.
 */
public abstract class RsConnectionBodyHandler {
    /** A body handler; subclasses say what to do with the body. */
    public RsConnectionBodyHandler() {
    }

    /**
     * Called when a body specification arrives: on the thread that reads the connection (or feeds it
     * bytes), or, for a client connected directly, on the client's thread calling
     * {@code sendBodySpecification} (with a decoded copy of its body).
     */
    public abstract void process(RsBody body);
}
