package rp1.simulator.net;

import static rp1.rossum.wire.Closing.closeQuietly;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;
import rp1.simulator.session.ClientBudgets;
import rp1.simulator.session.ClientSession;

/**
 * The network clients (docs/behavior.md section 3.3, docs/protocol.md section 4): one thread, the
 * "network" thread, accepts connections and reads every client's messages through one selector. Each
 * client's bytes go to its connection ({@code RsConnection.receive}), which does the CONNECT/ACCEPT
 * handshake and hands every complete request to the client's session as an input of the simulation;
 * after each round of reading the network thread runs the tasks then due itself
 * ({@link Simulation#pump()}), saving a thread hand-off per interlocked exchange.
 *
 * <p>A connection that does not complete its handshake within the time limit is closed with a log
 * line and holds up nobody (RP1 0.60 did the handshake on its one accepting thread, so a silent peer
 * blocked every later client). Within a round, the clients whose input has ended are dealt with
 * before anyone else's bytes: a robot whose client has gone leaves the world before any request that
 * reached the server after it (the simulation applies departures first at every boundary).
 *
 * <p>When accepting fails (the process has run out of file descriptors, say) the waiting connection
 * stays ready, so trying again at once would spin: accepting pauses for {@value #ACCEPT_PAUSE_MILLIS}
 * ms after each failure, and the failures are logged at most once a second. A client whose incomplete
 * message grows beyond its budget ({@code clientMessageBudget}) is disconnected.
 *
 * <p>Sockets are non-blocking channels with Nagle's algorithm off: events go out at once from the
 * thread that sends them while the client keeps up, and through its {@link OutboundQueue} when not.
 */
public final class ClientListener {
    private static final int READ_BUFFER_BYTES = 64 * 1024;
    /** Bytes read from one client per round before the others get their turn. */
    private static final int MAX_BYTES_PER_ROUND = 256 * 1024;
    static final long ACCEPT_PAUSE_MILLIS = 100;
    private static final long ACCEPT_LOG_INTERVAL_NANOS = 1_000_000_000L;

    /** Takes the next waiting connection, or null if none waits; a seam for tests of failing accepts. */
    @FunctionalInterface
    interface Acceptor {
        SocketChannel accept(ServerSocketChannel server) throws IOException;
    }

    private final ServerSocketChannel serverSocket;
    private final Selector selector;
    private final Simulation simulation;
    private final ClientRegistry clients;
    private final RsLogInterface log;
    private final long connectTimeoutNanos;
    private final int queueLimit;
    private final ClientBudgets budgets;
    private final Acceptor acceptor;
    /** When accepting may start again after a failure (System.nanoTime), or 0 while it is not paused. */
    private long acceptPausedUntil;
    /** When a failure to accept was last logged, and how many failed since without a line. */
    private long acceptFailureLogged;
    private int acceptFailuresUnlogged;
    private final ByteBuffer readBuffer = ByteBuffer.allocate(READ_BUFFER_BYTES);
    private final List<Peer> introducing = new ArrayList<>();
    private volatile boolean closed;
    /** What all the clients' incomplete messages may hold, and hold now (as last counted: see {@link #checkMessageBudget}). */
    private final long allIncomplete;
    private long incomplete;
    /** What the events waiting for all the clients may hold. */
    private final SharedBudget allOutput;
    /** Seconds a client may keep the interlock waiting (0: as long as it takes). */
    private final double interlockTimeout;

    private ClientListener(ServerSocketChannel serverSocket, Selector selector, Simulation simulation,
                           ClientRegistry clients, RsLogInterface log, Settings settings) {
        this.serverSocket = serverSocket;
        this.selector = selector;
        this.simulation = simulation;
        this.clients = clients;
        this.log = log;
        this.connectTimeoutNanos = Math.max(1L, Math.round(settings.connectTimeout * 1.0e9));
        this.queueLimit = settings.queueLimit;
        this.budgets = settings.budgets;
        this.acceptor = settings.acceptor;
        this.allIncomplete = settings.allClients;
        this.allOutput = new SharedBudget(settings.allClients);
        this.interlockTimeout = settings.interlockTimeout;
    }

    /** What a listener needs besides its address. */
    public static final class Settings {
        final double connectTimeout;
        final int queueLimit;
        final ClientBudgets budgets;
        final Acceptor acceptor;
        /**
         * Bytes all the clients together may make the server hold in incomplete messages, and again in
         * events they do not read: a quarter of the JVM's heap each, unless a test says otherwise.
         */
        final long allClients;
        /** Wall seconds a client may keep the interlock waiting before it is disconnected; 0: as long as it takes. */
        final double interlockTimeout;

        /**
         * @param connectTimeout seconds a new connection may take to send CONNECT
         * @param queueLimit     events that may wait for a client before it is disconnected
         */
        public Settings(double connectTimeout, int queueLimit) {
            this(connectTimeout, queueLimit, ClientBudgets.DEFAULTS);
        }

        /**
         * @param connectTimeout seconds a new connection may take to send CONNECT
         * @param queueLimit     events that may wait for a client before it is disconnected
         * @param budgets        what each client may make the server hold
         */
        public Settings(double connectTimeout, int queueLimit, ClientBudgets budgets) {
            this(connectTimeout, queueLimit, budgets, ServerSocketChannel::accept, Runtime.getRuntime().maxMemory() / 4, 0);
        }

        private Settings(double connectTimeout, int queueLimit, ClientBudgets budgets, Acceptor acceptor, long allClients,
                         double interlockTimeout) {
            this.connectTimeout = connectTimeout;
            this.queueLimit = queueLimit;
            this.budgets = budgets;
            this.acceptor = acceptor;
            this.allClients = allClients;
            this.interlockTimeout = interlockTimeout;
        }

        /** The same settings, taking connections with {@code a} (tests make accepting fail). */
        Settings withAcceptor(Acceptor a) {
            return new Settings(connectTimeout, queueLimit, budgets, a, allClients, interlockTimeout);
        }

        /**
         * The same settings, disconnecting a client that keeps the interlock waiting for more than
         * {@code seconds} of wall time ({@code interlockTimeout}; 0: as long as it takes).
         */
        public Settings withInterlockTimeout(double seconds) {
            return new Settings(connectTimeout, queueLimit, budgets, acceptor, allClients, seconds);
        }

        /**
         * The same settings with what all the clients together may make the server hold, in incomplete
         * messages and again in events waiting for them (by default a quarter of the JVM's heap each).
         */
        public Settings withAllClients(long bytes) {
            return new Settings(connectTimeout, queueLimit, budgets, acceptor, bytes, interlockTimeout);
        }
    }

    /**
     * Binds to {@code bindAddress:port} (port 0: any free port, see {@link #getPort()}); accepting
     * starts with {@link #start()}.
     *
     * @throws IOException if the address cannot be bound, e.g. the port is in use
     */
    public static ClientListener bind(String bindAddress, int port, Simulation simulation, ClientRegistry clients,
                                      RsLogInterface log, Settings settings) throws IOException {
        ServerSocketChannel s = ServerSocketChannel.open();
        Selector selector = null;
        try {
            s.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
            s.configureBlocking(false);
            selector = Selector.open();
            s.register(selector, SelectionKey.OP_ACCEPT);
        } catch (IOException e) {
            s.close();
            if (selector != null) {
                selector.close();
            }
            throw e;
        }
        return new ClientListener(s, selector, simulation, clients, log, settings);
    }

    /** The port clients connect to. */
    public int getPort() {
        return serverSocket.socket().getLocalPort();
    }

    /** Starts the network thread. */
    public void start() {
        Thread t = new Thread(this::serve, "network");
        t.setDaemon(true);
        t.start();
    }

    /** One client as the network thread sees it. */
    private static final class Peer {
        final SocketChannel channel;
        final ClientConnection connection;
        /** Its session in the simulation. */
        final ClientSession session;
        final long deadline;
        /** What was read this round, one array per read, in order; the connection joins split messages. */
        final List<byte[]> unread = new ArrayList<>();
        boolean ended;
        /** The bytes of its incomplete message as last counted in {@link #incomplete}. */
        int held;

        Peer(SocketChannel channel, ClientConnection connection, ClientSession session, long deadline) {
            this.channel = channel;
            this.connection = connection;
            this.session = session;
            this.deadline = deadline;
        }
    }

    private void serve() {
        log.log("Now accepting connections on " + serverSocket.socket().getLocalSocketAddress());
        try {
            while (!closed) {
                selector.select(selectTimeoutMillis());
                round();
            }
        } catch (IOException | RuntimeException e) {
            if (!closed) {
                log.logIt("X", "The network thread failed, no more network clients: " + e);
            }
        } finally {
            closeQuietly(selector);
        }
    }

    /** Until the next handshake falls due or accepting resumes, at most a second; 0 would mean for ever. */
    private long selectTimeoutMillis() {
        long next = acceptPausedUntil != 0 ? acceptPausedUntil : Long.MAX_VALUE;
        for (Peer p : introducing) {
            next = Math.min(next, p.deadline);
        }
        if (next == Long.MAX_VALUE) {
            return 1000;
        }
        return Math.max(1L, Math.min(1000L, (next - System.nanoTime()) / 1_000_000L + 1));
    }

    /**
     * One round: accept what is waiting, read what every ready client sent, then hand it over, the
     * clients whose input ended first; then run what is due.
     */
    private void round() throws IOException {
        resumeAccepting();
        List<Peer> ready = new ArrayList<>();
        Iterator<SelectionKey> keys = selector.selectedKeys().iterator();
        while (keys.hasNext()) {
            SelectionKey key = keys.next();
            keys.remove();
            if (!key.isValid()) {
                continue;
            }
            if (key.isAcceptable()) {
                acceptAll();
            } else if (key.isReadable()) {
                Peer p = (Peer) key.attachment();
                read(p);
                ready.add(p);
            }
        }
        for (Peer p : ready) {
            if (p.ended) {
                deliver(p);
            }
        }
        for (Peer p : ready) {
            if (!p.ended) {
                deliver(p);
            }
        }
        expireHandshakes();
        disconnectOverdue();
        simulation.pump();
    }

    /**
     * With an {@code interlockTimeout}, a client that has kept simulated time waiting longer is
     * disconnected, so that one client that stopped answering cannot stop the world for the others.
     */
    private void disconnectOverdue() {
        if (interlockTimeout <= 0) {
            return;
        }
        List<ClientSession> late = simulation.overdueSessions(interlockTimeout);
        if (late.isEmpty()) {
            return;
        }
        for (SelectionKey key : selector.keys()) {
            if (key.attachment() instanceof Peer p && late.contains(p.session) && !p.connection.hasEnded()) {
                p.connection.close("it did not acknowledge an event within " + interlockTimeout + " s (interlockTimeout)");
            }
        }
    }

    private void acceptAll() {
        while (true) {
            SocketChannel channel;
            try {
                channel = acceptor.accept(serverSocket);
            } catch (IOException e) {
                if (!closed) {
                    acceptFailed(e);
                }
                return;
            }
            if (channel == null) {
                return;
            }
            accepted(channel);
        }
    }

    /**
     * The connection that could not be accepted still waits, and the selector would report it again
     * at once: stop asking for it for a while, and log the failure at most once a second.
     */
    private void acceptFailed(IOException e) {
        long now = System.nanoTime();
        serverSocket.keyFor(selector).interestOps(0);
        acceptPausedUntil = now + ACCEPT_PAUSE_MILLIS * 1_000_000L;
        if (acceptFailureLogged != 0 && now - acceptFailureLogged < ACCEPT_LOG_INTERVAL_NANOS) {
            acceptFailuresUnlogged++;
            return;
        }
        String more = acceptFailuresUnlogged == 0 ? "" : " (" + acceptFailuresUnlogged + " more failures since the last line)";
        log.logIt("X", "Accepting a connection failed: " + e.getMessage() + more + "; trying again every "
                + ACCEPT_PAUSE_MILLIS + " ms");
        acceptFailureLogged = now;
        acceptFailuresUnlogged = 0;
    }

    private void resumeAccepting() {
        if (acceptPausedUntil != 0 && System.nanoTime() - acceptPausedUntil >= 0) {
            acceptPausedUntil = 0;
            serverSocket.keyFor(selector).interestOps(SelectionKey.OP_ACCEPT);
        }
    }

    private void accepted(SocketChannel channel) {
        String address;
        try {
            address = String.valueOf(channel.getRemoteAddress());
        } catch (IOException e) {
            closeQuietly(channel);
            return;
        }
        String description = "client " + clients.nextNumber() + " (" + address + ")";
        ClientConnection c = new ClientConnection(description);
        if (!clients.add(c)) {
            closeQuietly(channel);
            return;
        }
        try {
            channel.configureBlocking(false);
            channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
            OutboundQueue out = OutboundQueue.start(new ChannelTransport(channel), queueLimit, budgets.output, allOutput,
                    "writer " + description, c::close);
            c.setInputOutputStreams(null, out);
            ClientSession session = simulation.attach(c, description, Simulation.Link.SHARED_READER);
            Peer p = new Peer(channel, c, session, System.nanoTime() + connectTimeoutNanos);
            channel.register(selector, SelectionKey.OP_READ, p);
            introducing.add(p);
        } catch (IOException e) {
            c.close("cannot set up the connection: " + e.getMessage());
            closeQuietly(channel);
        }
    }

    /** Reads what the client has sent (up to a round's share); notes the end of its input. */
    private void read(Peer p) {
        int total = 0;
        try {
            while (total < MAX_BYTES_PER_ROUND) {
                readBuffer.clear();
                int n = p.channel.read(readBuffer);
                if (n < 0) {
                    p.ended = true;
                    break;
                }
                if (n == 0) {
                    break;
                }
                p.unread.add(Arrays.copyOf(readBuffer.array(), n));
                total += n;
            }
        } catch (ClosedChannelException e) {
            p.ended = true;
        } catch (IOException e) {
            p.ended = true;
            if (!p.connection.hasEnded()) {
                log.log(p.connection.getDescription() + ": reading failed: " + e.getMessage());
            }
        }
    }

    /**
     * Hands the bytes read to the client's connection, read by read; ends the session on a protocol
     * error, a failing request handler, or the end of input.
     */
    private void deliver(Peer p) {
        ClientConnection c = p.connection;
        if (c.hasEnded()) {
            p.unread.clear();
            closeQuietly(p.channel);
            return;
        }
        boolean wasIntroduced = c.hasIntroduced();
        try {
            for (byte[] chunk : p.unread) {
                c.receive(chunk, 0, chunk.length);
                checkMessageBudget(p);
            }
        } catch (IOException e) {
            String reason = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
            if (c.hasIntroduced()) {
                c.inputFailed(reason);
            } else {
                handshakeFailed(p, reason);
            }
            closeQuietly(p.channel);
            return;
        } catch (RuntimeException e) {
            // One client's message must not stop the network thread, which reads every client.
            introducing.remove(p);
            StringWriter trace = new StringWriter();
            e.printStackTrace(new PrintWriter(trace));
            c.close("handling its message failed: " + trace);
            closeQuietly(p.channel);
            return;
        } finally {
            p.unread.clear();
        }
        if (!wasIntroduced && c.hasIntroduced()) {
            introducing.remove(p);
            log.log(c.getDescription() + " connected (" + c.getIdentity() + ")");
        }
        if (p.ended) {
            introducing.remove(p);
            if (c.hasIntroduced()) {
                c.endOfInput();
            } else {
                handshakeFailed(p, "the connection closed before CONNECT");
            }
            closeQuietly(p.channel);
        }
    }

    /**
     * A client whose incomplete message has outgrown its budget is refused like a protocol error; so is
     * one whose message would take the clients' incomplete messages together beyond what they all may
     * hold (many connections, each within its own budget, ran a server out of memory).
     */
    private void checkMessageBudget(Peer p) throws IOException {
        int held = p.connection.getIncompleteMessageBytes();
        if (held > budgets.message) {
            throw new IOException("over budget: an incomplete message of " + held + " bytes, the budget is "
                    + budgets.message + " (clientMessageBudget)");
        }
        incomplete += held - p.held;
        p.held = held;
        // The running count keeps what clients that have gone held (it can only be too high): it is
        // counted again, from the clients still here, before anyone is refused.
        if (incomplete > allIncomplete && countIncomplete() > allIncomplete) {
            throw new IOException("over budget: the clients' incomplete messages would hold " + incomplete + " bytes"
                    + " in all, more than the " + allIncomplete + " they all may (a quarter of the server's memory);"
                    + " this client's is " + held + " bytes");
        }
    }

    /** The bytes of every open client's incomplete message, counted anew. */
    private long countIncomplete() {
        long total = 0;
        for (SelectionKey key : selector.keys()) {
            if (key.attachment() instanceof Peer q) {
                q.held = q.connection.hasEnded() ? 0 : q.connection.getIncompleteMessageBytes();
                total += q.held;
            }
        }
        incomplete = total;
        return total;
    }


    private void expireHandshakes() {
        long now = System.nanoTime();
        Iterator<Peer> it = introducing.iterator();
        while (it.hasNext()) {
            Peer p = it.next();
            if (p.connection.hasEnded()) {
                it.remove();
            } else if (now - p.deadline >= 0) {
                it.remove();
                handshakeFailed(p, "no CONNECT within " + connectTimeoutNanos / 1_000_000L + " ms (connectTimeout)");
                    closeQuietly(p.channel);
            }
        }
    }

    private void handshakeFailed(Peer p, String reason) {
        introducing.remove(p);
        log.log(p.connection.getDescription() + ": handshake failed: " + reason);
        p.connection.close("handshake failed");
    }

    /** Stops accepting and reading; the connections already made are closed by their registry. */
    public void close() {
        closed = true;
        closeQuietly(serverSocket);
        selector.wakeup();
    }
}
