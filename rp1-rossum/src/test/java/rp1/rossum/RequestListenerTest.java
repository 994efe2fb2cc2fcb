package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsEvent;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireOut;

/**
 * A connection with a request listener hands it every request and the body, one typed call each,
 * and leaves RP1 0.60's per-type handlers and subscription table alone; without one, the 0.60
 * handlers and table get them, as a 0.60 server expects.
 */
class RequestListenerTest {
    private static byte[] session() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] body = RsConnection.encodeBodySpecification(bodyOf("lis"));
        write(b, new WireOut().header(7, 9, 0, RsProtocol.CONNECT));
        write(b, new WireOut().header(7, 9, 1, RsProtocol.BODY_SPECIFICATION));
        b.write(body, 0, body.length);
        request(b, 2, RequestCodec.subscription(RsEvent.EVT_CONTACT_SENSOR, 3, true));
        request(b, 3, RequestCodec.timeout(-0.5, 4));
        request(b, 4, RequestCodec.placement("home"));
        request(b, 5, new WireOut().i32(6).i32(0));
        return b.toByteArray();
    }

    private static RsBody bodyOf(String name) {
        RsBody body = new RsBody(name);
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
        return body;
    }

    private static void request(ByteArrayOutputStream b, int sequence, WireOut payload) {
        write(b, new WireOut().header(7, 9, sequence, RsProtocol.REQUEST));
        write(b, payload);
    }

    private static void write(ByteArrayOutputStream b, WireOut w) {
        byte[] bytes = w.toByteArray();
        b.write(bytes, 0, bytes.length);
    }

    private static RsConnection connection() {
        RsConnection c = new RsConnection();
        c.setLogger(null);
        c.setInputOutputStreams(null, new ByteArrayOutputStream());
        return c;
    }

    @Test
    void aListenerGetsEveryRequestAndTheBodyAndTheOldHandlersNothing() throws Exception {
        RsConnection c = connection();
        ServerRecorder handlers = new ServerRecorder(c);
        RecordingSink listener = new RecordingSink();
        c.setRequestListener(listener);
        byte[] bytes = session();
        c.receive(bytes, 0, bytes.length);
        assertEquals(List.of("body", "subscription", "timeout", "placement", "setPosition"), listener.calls);
        assertEquals(-0.5, listener.timeoutDuration);
        assertEquals(4, listener.timeoutIndex);
        assertEquals(null, handlers.received.poll(0), "a 0.60 handler was called although a listener is set");
        assertFalse(c.isClientSubscribedToEvent(RsEvent.EVT_CONTACT_SENSOR, 3));
    }

    @Test
    void withoutAListenerThe060HandlersAndTableGetThem() throws Exception {
        RsConnection c = connection();
        ServerRecorder handlers = new ServerRecorder(c);
        byte[] bytes = session();
        c.receive(bytes, 0, bytes.length);
        List<Object> got = new ArrayList<>();
        Object o;
        while ((o = handlers.received.poll(0)) != null) {
            got.add(o);
        }
        assertEquals(4, got.size(), "body, subscription, timeout and placement: " + got);
        assertTrue(got.get(0) instanceof RsBody);
        assertTrue(c.isClientSubscribedToEvent(RsEvent.EVT_CONTACT_SENSOR, 3));
    }
}
