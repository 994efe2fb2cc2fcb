package rp1.rossum;

/** Called once when a connection shuts down (the peer went away or broke the protocol). */
public interface RsProtocolShutdownHandler {
    void process();
}
