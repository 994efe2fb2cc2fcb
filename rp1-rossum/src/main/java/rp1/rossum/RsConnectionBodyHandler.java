package rp1.rossum;

/**
 * Server side: receives the robot body a client specified, so that the simulator can put the robot
 * into its world. The simulator registers one with {@link RsConnection#setBodyHandler}.
 */
public abstract class RsConnectionBodyHandler {
    public RsConnectionBodyHandler() {
    }

    /** Called, on the thread that reads the connection (or feeds it bytes), when a body specification arrives. */
    public abstract void process(RsBody body);
}
