package rp1.rossum;

import java.util.function.Consumer;

import rp1.rossum.event.RsEvent;

/**
 * A client and the server's end of its session in one process, without streams
 * ({@link RsConnection#connectDirect}). Requests go from the client straight into the connection's
 * dispatch; events go from the connection straight into the client's handlers, on the sending thread.
 * What crosses is what the wire would deliver: the body as a decoded copy, every event as the copy
 * the client would decode ({@link EventCodec#copy}), requests as the objects the server would decode
 * (the client builds them so).
 */
final class DirectLink {
    private final RsConnection server;
    private final RsClient client;
    private final Consumer<Throwable> onFailure;

    DirectLink(RsConnection server, RsClient client, Consumer<Throwable> onFailure) {
        this.server = server;
        this.client = client;
        this.onFailure = onFailure;
    }

    /** Where the client's requests go. */
    RequestSink requests() {
        return server.dispatcher();
    }

    /**
     * The client's body, as the server would decode it from the wire (decoding sets the process-wide
     * part counter exactly as it does for a client over pipes).
     */
    void body(RsBody body) {
        RsBody copy;
        try {
            copy = BodyCodec.decode(BodyCodec.encode(body));
        } catch (java.io.IOException e) {
            throw new IllegalStateException("a body this library encoded cannot be decoded", e);
        }
        server.directBody(copy);
    }

    /**
     * Runs the client's handlers for {@code event}. A handler's RuntimeException is reported by the
     * client and the event goes on to the next handler, as over the wire; an Error ends the session.
     */
    void deliver(RsEvent event) {
        try {
            client.receiveDirect(EventCodec.copy(event));
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
}
