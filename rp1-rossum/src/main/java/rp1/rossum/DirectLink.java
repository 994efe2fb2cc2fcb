package rp1.rossum;

import java.util.function.Consumer;

import rp1.rossum.event.RsEvent;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.RequestListener;

/**
 * A client and the server's end of its session in one process, without streams
 * ({@link RsConnection#connectDirect}). Requests go from the client straight into the connection's
 * listener; events go from the connection straight into the client's handlers, on the sending thread.
 * What crosses is what the wire would deliver: the body as the copy decoded from its payload,
 * every event as the copy the client would decode ({@link EventCodec#copy}), every request as the
 * object the server would decode ({@link RequestCodec#copying}). The client builds its requests for the
 * wire; this link alone pays for making them look decoded.
 */
final class DirectLink {
    private final RsConnection server;
    private final RsClient client;
    private final Consumer<Throwable> onFailure;
    private final RequestListener requests;

    DirectLink(RsConnection server, RsClient client, Consumer<Throwable> onFailure) {
        this.server = server;
        this.client = client;
        this.onFailure = onFailure;
        this.requests = RequestCodec.copying(server::requests);
    }

    /** Where the client's requests go: copied as decoding would give them, then the server's listener. */
    RequestListener requests() {
        return requests;
    }

    /**
     * The client's body as the server would decode it from the wire ({@link BodyCodec#checked} of its
     * payload): every part keeps the id it has in the client's body, and the client's later changes
     * to its own body do not reach it.
     */
    void body(RsBody decoded) {
        server.bodyReceived(decoded);
    }

    /**
     * Runs the client's handlers for {@code event}. A handler's RuntimeException is reported by the
     * client and the event goes on to the next handler, as over the wire; an Error ends the session,
     * a StackOverflowError or an OutOfMemoryError too (a handler that recursed too deep or allocated
     * too much: the stack has unwound to here and what it held can be collected, as on the client's
     * own thread over a pipe, where either ends the client alone). Another failure of the JVM itself
     * (an InternalError) is not the client's and goes on up.
     */
    void deliver(RsEvent event) {
        try {
            client.receiveDirect(EventCodec.copy(event));
        } catch (StackOverflowError | OutOfMemoryError e) {
            onFailure.accept(e);
            close();
        } catch (VirtualMachineError e) {
            throw e;
        } catch (Throwable t) {
            onFailure.accept(t);
            close();
        }
    }

    /** Ends the session on both sides. */
    void close() {
        server.shutdown();
        client.shutdown();
    }

    /** The client's closing action: its session ended, so the server's end closes. */
    void shutdownServer() {
        server.shutdown();
    }

    /** The server's closing action: its end of the session closed, so the client's session ends. */
    void shutdownClient() {
        client.shutdown();
    }
}
