package rp1.simulator.net;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import rp1.rossum.RsLogInterface;

/**
 * The server's open client connections, network and in-process alike: numbers new clients (1, 2, 3,
 * ... in order of arrival, for log lines), logs each disconnection, and closes every connection when
 * the server stops.
 */
public final class ClientRegistry {
    private final RsLogInterface log;
    private final AtomicInteger numbers = new AtomicInteger();
    private final Set<ClientConnection> open = ConcurrentHashMap.newKeySet();
    private volatile boolean closing;

    /** A registry logging disconnections to {@code log}. */
    public ClientRegistry(RsLogInterface log) {
        this.log = log;
    }

    /** The number of the next client. */
    public int nextNumber() {
        return numbers.incrementAndGet();
    }

    /**
     * Adds a connection; when its session ends it is removed again and a line says so. Once the
     * server is stopping, connections are refused: the caller gets false and the connection is closed.
     */
    public boolean add(ClientConnection c) {
        c.addEndListener(() -> {
            open.remove(c);
            log.log(c.getDescription() + " disconnected");
        });
        open.add(c);
        if (closing) {
            open.remove(c);
            c.close("the server is shutting down");
            return false;
        }
        return true;
    }

    /** The number of open connections (including those still in their handshake). */
    public int size() {
        return open.size();
    }

    /**
     * Refuses new connections and closes every open one, logging {@code reason} for each; returns once
     * each one's end has been logged (a client leaving on its own at that moment included), at most a
     * second per connection.
     */
    public void closeAll(String reason) {
        closing = true;
        List<ClientConnection> all = new ArrayList<>(open);
        for (ClientConnection c : all) {
            c.close(reason);
        }
        // One second for them all, not each: a server with hundreds of clients still stops at once.
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(1);
        try {
            for (ClientConnection c : all) {
                c.awaitEnded(Math.max(0L, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        open.clear();
    }
}
