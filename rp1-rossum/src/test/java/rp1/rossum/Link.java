package rp1.rossum;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * A client and a server connection talking to each other, either in-process over {@link RsPipe}s
 * (no handshake, as a dynamically loaded client), in-process without streams (a direct link), or over a
 * loopback socket on an ephemeral port (with the CONNECT/ACCEPT handshake). The connection's reader runs on its own thread; the client's
 * event loop is started with {@link #startClientLoop()}.
 */
final class Link implements AutoCloseable {
    final RsClient client;
    final RsConnection connection;
    final Capture<Boolean> clientShutdown = new Capture<>();
    final Capture<Boolean> connectionShutdown = new Capture<>();
    private Thread serverThread;
    private Thread clientThread;
    private boolean direct;

    private Link(RsClient client, RsConnection connection) {
        this.client = client;
        this.connection = connection;
        client.setProtocolShutdownHandler(() -> clientShutdown.add(true));
        connection.setProtocolShutdownHandler(() -> connectionShutdown.add(true));
    }

    /** In-process: two pipes, no handshake. */
    static Link piped(RsClient client, RsConnection connection) {
        Link link = new Link(client, connection);
        RsPipe toServer = new RsPipe();
        RsPipe toClient = new RsPipe();
        connection.setInputOutputStreams(toServer.getInputStream(), toClient.getOutputStream());
        client.setInputOutputStreams(toClient.getInputStream(), toServer.getOutputStream());
        return link;
    }

    /** In-process without streams: the client's handlers run on the thread that sends each event. */
    static Link direct(RsClient client, RsConnection connection) {
        Link link = new Link(client, connection);
        connection.connectDirect(client, t -> {
            throw new AssertionError("a client handler failed", t);
        });
        link.direct = true;
        return link;
    }

    /** Over a loopback socket, with the real client connect path and the handshake. */
    static Link socket(RsClient client, RsConnection connection) throws Exception {
        Link link = new Link(client, connection);
        try (ServerSocket listener = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            CompletableFuture<Void> accepted = CompletableFuture.runAsync(() -> {
                try {
                    Socket s = listener.accept();
                    connection.setSocket(s);
                    connection.exchangeIntroductions();
                } catch (IOException e) {
                    throw new RuntimeException(e);
                }
            });
            RsProperties p = new RsProperties();
            p.port = listener.getLocalPort();
            p.hostName = "127.0.0.1";
            client.initiateConnection(p);
            accepted.get(10, TimeUnit.SECONDS);
        }
        return link;
    }

    /** Starts the server connection's reader thread (a direct link has none: requests arrive as they are sent). */
    Link startServer() {
        if (direct) {
            return this;
        }
        serverThread = new Thread(connection, "test-connection");
        serverThread.setDaemon(true);
        serverThread.start();
        return this;
    }

    /** Starts the client's event loop on its own thread. */
    Link startClientLoop() {
        clientThread = new Thread(client, "test-client");
        clientThread.setDaemon(true);
        clientThread.start();
        return this;
    }

    /** Waits (bounded) for the client's event loop to return. */
    void awaitClientLoopEnd() throws InterruptedException {
        clientThread.join(10_000);
        if (clientThread.isAlive()) {
            throw new AssertionError("RsClient.run() did not return within 10 s");
        }
    }

    @Override
    public void close() {
        client.shutdown();
        connection.shutdown();
    }
}
