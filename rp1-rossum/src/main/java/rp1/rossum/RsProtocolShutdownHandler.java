package rp1.rossum;

/** Called once when a connection shuts down (the peer went away or broke the protocol). */
public interface RsProtocolShutdownHandler {
    /** Called once, on the thread that ended the session, after the streams were closed. */
    void process();
}
