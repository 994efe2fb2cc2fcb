package rp1.simulator.net;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;

/**
 * Accepts network clients (behavior.md section 3.3, protocol.md section 4): a listener thread accepts
 * connections; each gets a thread of its own that performs the CONNECT/ACCEPT handshake under a time
 * limit, attaches the client to the simulation and then reads its requests. A client that connects
 * and stays silent, or breaks the handshake, is dropped with a log line and holds up nobody (RP1 0.60
 * did the handshake on its one accepting thread, so a silent peer blocked every later client).
 *
 * <p>Sockets are non-blocking channels with Nagle's algorithm off: events go out at once from the
 * thread that sends them while the client keeps up, and through its {@link OutboundQueue} when not.
 */
public final class ClientListener {
    private final ServerSocketChannel serverSocket;
    private final Simulation simulation;
    private final ClientRegistry clients;
    private final RsLogInterface log;
    private final int connectTimeoutMillis;
    private final int queueLimit;
    private volatile boolean closed;

    private ClientListener(ServerSocketChannel serverSocket, Simulation simulation, ClientRegistry clients,
                           RsLogInterface log, int connectTimeoutMillis, int queueLimit) {
        this.serverSocket = serverSocket;
        this.simulation = simulation;
        this.clients = clients;
        this.log = log;
        this.connectTimeoutMillis = connectTimeoutMillis;
        this.queueLimit = queueLimit;
    }

    /** What a listener needs besides its address. */
    public static final class Settings {
        final double connectTimeout;
        final int queueLimit;

        /**
         * @param connectTimeout seconds a new connection may take to send CONNECT
         * @param queueLimit     events that may wait for a client before it is disconnected
         */
        public Settings(double connectTimeout, int queueLimit) {
            this.connectTimeout = connectTimeout;
            this.queueLimit = queueLimit;
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
        try {
            s.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
        } catch (IOException e) {
            s.close();
            throw e;
        }
        int timeout = (int) Math.max(1L, Math.min(Integer.MAX_VALUE, Math.round(settings.connectTimeout * 1000.0)));
        return new ClientListener(s, simulation, clients, log, timeout, settings.queueLimit);
    }

    /** The port clients connect to. */
    public int getPort() {
        return serverSocket.socket().getLocalPort();
    }

    /** Starts the listener thread. */
    public void start() {
        Thread t = new Thread(this::acceptLoop, "listener");
        t.setDaemon(true);
        t.start();
    }

    private void acceptLoop() {
        log.log("Now accepting connections on " + serverSocket.socket().getLocalSocketAddress());
        while (!closed) {
            SocketChannel channel;
            String address;
            try {
                channel = serverSocket.accept();
                address = String.valueOf(channel.getRemoteAddress());
            } catch (IOException e) {
                if (!closed) {
                    log.logIt("X", "The listener failed, no more network clients: " + e.getMessage());
                }
                return;
            }
            int n = clients.nextNumber();
            String description = "client " + n + " (" + address + ")";
            Thread t = new Thread(() -> serve(channel, description), "client " + n);
            t.setDaemon(true);
            t.start();
        }
    }

    /** The thread of one network client: handshake, then its requests until it leaves. */
    private void serve(SocketChannel channel, String description) {
        ClientConnection c = new ClientConnection(description);
        if (!clients.add(c)) {
            closeQuietly(channel);
            return;
        }
        try {
            channel.configureBlocking(false);
            channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
            ChannelInput in = new ChannelInput(channel);
            in.setTimeout(connectTimeoutMillis);
            OutboundQueue out = OutboundQueue.start(new ChannelTransport(channel), queueLimit, "writer " + description,
                    c::close);
            c.setInputOutputStreams(in, out);
            c.exchangeIntroductions();
            in.setTimeout(0);
        } catch (SocketTimeoutException e) {
            handshakeFailed(channel, c, "no CONNECT within " + connectTimeoutMillis + " ms (connectTimeout)");
            return;
        } catch (IOException e) {
            handshakeFailed(channel, c, e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName());
            return;
        }
        simulation.attach(c, description, Simulation.Link.READER);
        log.log(description + " connected (" + c.getIdentity() + ")");
        c.run();
    }

    private void handshakeFailed(SocketChannel channel, ClientConnection c, String reason) {
        log.log(c.getDescription() + ": handshake failed: " + reason);
        c.close("handshake failed");
        closeQuietly(channel);
    }

    /** Stops accepting; connections already made stay open. */
    public void close() {
        closed = true;
        closeQuietly(serverSocket);
    }

    private static void closeQuietly(AutoCloseable c) {
        try {
            c.close();
        } catch (Exception ignored) {
            // Closing a socket that is being abandoned; nothing useful to do if it fails.
        }
    }
}
