package rp1.simulator.net;

import java.io.IOException;
import java.io.OutputStream;
import java.util.function.Function;

import rp1.rossum.RsConnection;
import rp1.rossum.RsPipe;
import rp1.rossum.RsRunnable;
import rp1.simulator.Simulation;
import rp1.simulator.session.ClientSession;

/**
 * A client connected to a simulation in the same process through a pair of {@link RsPipe}s, with no
 * handshake, as RP1's dynamically loaded clients are (docs/behavior.md section 3.4): the server's end
 * is attached and its reader thread started (which runs the tasks due after each message it hands
 * over); the client is given the other ends. The caller then runs the client's {@code initialize()}
 * and {@code run()}.
 */
public final class InProcessClient {
    private final RsPipe toServer = new RsPipe();
    private final RsPipe toClient = new RsPipe();
    private final ClientSession session;
    private final Thread reader;

    /**
     * Connects {@code client} to {@code simulation}: the connection is attached and its reader thread
     * started, then {@code setInputOutputStreams} is called on the client and, if {@code shareLog},
     * {@code setLogger} with the simulation's log.
     */
    public InProcessClient(Simulation simulation, RsRunnable client, String description, boolean shareLog) {
        this(simulation, client, description, shareLog, new RsConnection(), RsPipe::getOutputStream);
    }

    /**
     * Connects {@code client} as above, with {@code connection} as the server's end, which writes to
     * the client through the stream {@code outbound} makes of the pipe to the client (the server puts a
     * bounded queue there so that a client that stops reading cannot hold up the simulation).
     */
    public InProcessClient(Simulation simulation, RsRunnable client, String description, boolean shareLog,
                           RsConnection connection, Function<RsPipe, OutputStream> outbound) {
        connection.setInputOutputStreams(toServer.getInputStream(), outbound.apply(toClient));
        session = simulation.attach(connection, description, Simulation.Link.READER);
        reader = new Thread(connection, "connection " + description);
        reader.setDaemon(true);
        reader.start();
        client.setInputOutputStreams(toClient.getInputStream(), toServer.getOutputStream());
        if (shareLog) {
            client.setLogger(simulation.getLog());
        }
    }

    /** The client's session in the simulation. */
    public ClientSession session() {
        return session;
    }

    /**
     * Whether the server has dealt with everything the client sent so far (its reader is waiting for
     * more). A lockstep simulation starts its clock once its in-process clients are drained after
     * {@code initialize()}, so their first requests are all stamped at time 0.
     */
    public boolean isDrained() {
        // A client that has already ended (its run() threw at once): drained once the reader has also
        // dealt with the end, its robot's leaving, so that this happens before the clock starts too.
        return toServer.isDrained() && !(toServer.isAtEnd() && reader.isAlive());
    }

    /** Waits until {@link #isDrained()}, at most {@code millis}; returns whether it is. */
    public boolean awaitDrained(long millis) throws InterruptedException {
        long deadline = System.nanoTime() + millis * 1_000_000L;
        while (!isDrained()) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            Thread.sleep(1);
        }
        return true;
    }

    /** Closes both pipes: the client's event loop ends, and the server removes its robot. */
    public void close() {
        try {
            toClient.getOutputStream().close();
            toServer.getOutputStream().close();
        } catch (IOException e) {
            throw new IllegalStateException("closing an in-memory pipe cannot fail", e);
        }
    }
}
