package rp1.simulator.net;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import rp1.rossum.RsConnection;

/**
 * The server's end of one client session as the server runs it: an {@link RsConnection} whose log
 * lines name the client ("client 3 (/127.0.0.1:40312): ..."), which the server can close with a
 * reason, and which tells its listeners once when the session has ended, whoever ended it.
 */
public final class ClientConnection extends RsConnection {
    private final String description;
    private final AtomicBoolean ended = new AtomicBoolean();
    private final CountDownLatch told = new CountDownLatch(1);
    private final List<Runnable> endListeners = new CopyOnWriteArrayList<>();
    /** Set when the server closed the session; the reader's own complaint about it is then noise. */
    private volatile boolean closedByServer;

    /** A connection for the client described as {@code description}, e.g. "client 3 (/127.0.0.1:40312)". */
    public ClientConnection(String description) {
        this.description = description;
    }

    /** Who the client is, for log lines. */
    public String getDescription() {
        return description;
    }

    /** The client id and key the handshake gave the session (both 0 in-process and for RP1 0.60's clients). */
    public String getIdentity() {
        return "client id " + clientID + ", key " + clientKey;
    }

    /** Runs {@code listener} once, after the session has ended (on the thread that ended it). */
    public void addEndListener(Runnable listener) {
        endListeners.add(listener);
    }

    @Override
    public void logIt(String level, String message) {
        if (!closedByServer) {
            super.logIt(level, description + ": " + message);
        }
    }

    /**
     * Ends the session from the server's side, logging {@code reason}: the streams close, the
     * client's robot leaves the world and any interlock it held is released. Does nothing if the
     * session already ended. Never blocks on the client.
     */
    public void close(String reason) {
        if (ended.get()) {
            return;
        }
        logIt("s", "closing the connection: " + reason);
        closedByServer = true;
        shutdown();
    }

    /** Whether the session has ended. */
    public boolean hasEnded() {
        return ended.get();
    }

    @Override
    protected void shutdown() {
        super.shutdown();
        if (ended.compareAndSet(false, true)) {
            try {
                for (Runnable listener : endListeners) {
                    listener.run();
                }
            } finally {
                told.countDown();
            }
        }
    }

    /**
     * Waits (at most {@code millis}) until the end listener has run, on whichever thread ended the
     * session: the server waits for this before closing its log.
     */
    public boolean awaitEnded(long millis) throws InterruptedException {
        return told.await(millis, TimeUnit.MILLISECONDS);
    }
}
