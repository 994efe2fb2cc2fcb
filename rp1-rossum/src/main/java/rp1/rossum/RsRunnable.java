package rp1.rossum;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;

/**
 * A client the simulator can load and run in its own process (a "dynamically loaded client"). The
 * server creates it with its public no-argument constructor, then calls, in this order,
 * {@link #setInputOutputStreams} (in-process pipes instead of a socket), {@link #setLogger} (the
 * server's log), {@link #initialize()} and {@link #run()} on a thread of its own. {@code RsClient}
 * implements it, so a class extending {@code RsClient} only needs the constructor.
 */
public interface RsRunnable extends Runnable {
    /** Use these streams to talk to the server instead of opening a socket. */
    void setInputOutputStreams(InputStream input, OutputStream output);

    /** Connect (unless streams were supplied), send the body, register handlers. */
    void initialize() throws IOException;

    /** Log through this logger; null disables logging. */
    void setLogger(RsLogInterface logger);
}
