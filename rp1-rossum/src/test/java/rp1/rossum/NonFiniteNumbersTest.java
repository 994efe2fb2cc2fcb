package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * Issue 18.3: NaN and the infinities in a request or a body. The server's decoder refuses them naming
 * the field (the session ends, protocol.md section 14); the client library refuses to send them,
 * naming the argument, and writes nothing.
 */
class NonFiniteNumbersTest {

    private static RsProtocolException refusedRequest(WireOut payload) {
        return assertThrows(RsProtocolException.class,
                () -> RequestCodec.decode(WireIn.of(payload.toByteArray()), new RecordingSink()));
    }

    @Test
    void theServerRefusesNaNAndInfinitiesInEveryFloatingPointFieldOfARequest() {
        RsActuatorControlRequest actuator = new RsActuatorControlRequest(1, RsActuatorControlRequest.ACTIVATE);
        actuator.addParameter("left", 1.0);
        actuator.addParameter("right", Double.NEGATIVE_INFINITY);
        Color[] red = {Color.RED};

        assertRefused("timeout duration", RequestCodec.timeout(Double.NaN, 1));
        assertRefused("motion linear velocity", RequestCodec.motion(new RsMotionRequest(Double.POSITIVE_INFINITY, 0, 1)));
        assertRefused("motion rotational velocity", RequestCodec.motion(new RsMotionRequest(0.5, Double.NaN, 1)));
        assertRefused("motion duration", RequestCodec.motion(new RsMotionRequest(0.5, 0, Double.NaN)));
        assertRefused("heartbeat interval", RequestCodec.heartbeat(Double.POSITIVE_INFINITY));
        assertRefused("painter trailer x", RequestCodec.painterActivation(7, Double.NaN, 0, 0.1, red));
        assertRefused("painter trailer y", RequestCodec.painterActivation(7, 0, Double.NaN, 0.1, red));
        assertRefused("painter trailer width", RequestCodec.painterActivation(7, 0, 0, Double.NaN, red));
        assertRefused("actuator parameter 1 value", RequestCodec.actuatorControl(actuator));
    }

    private static void assertRefused(String field, WireOut payload) {
        RsProtocolException e = refusedRequest(payload);
        assertEquals(field, e.getField());
        assertTrue(e.getMessage().endsWith("is not a finite number"), e.getMessage());
    }

    @Test
    void finiteExtremesStillPass() throws Exception {
        RecordingSink sink = new RecordingSink();
        RequestCodec.decode(WireIn.of(RequestCodec.timeout(-Double.MAX_VALUE, 1).toByteArray()), sink);
        assertEquals(-Double.MAX_VALUE, sink.timeoutDuration);
    }

    @Test
    void theServerRefusesABodyWithANonFiniteDimensionNamingThePart() {
        RsBody body = new RsBody("b");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        body.addPart(new RsBodyCircle(0.1, Double.NaN, 0.05));
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> BodyCodec.decode(BodyCodec.encode(body)));
        assertEquals("part[1].yCenter", e.getField());
        assertEquals("part[1].yCenter: NaN is not a finite number", e.getMessage());
    }

    /** A client whose output goes to {@code out}; nothing comes in. */
    private static RsClient clientWritingTo(ByteArrayOutputStream out) {
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        client.setInputOutputStreams(new ByteArrayInputStream(new byte[0]), out);
        return client;
    }

    private static void assertNotSent(String argument, Consumer<RsClient> send) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        RsClient client = clientWritingTo(out);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> send.accept(client));
        assertTrue(e.getMessage().startsWith(argument + " must be a finite number, got "), e.getMessage());
        assertEquals(0, out.size(), "nothing was written");
    }

    @Test
    void theClientRefusesToSendNonFiniteNumbersNamingTheArgument() {
        assertNotSent("duration", c -> c.sendTimeoutRequest(Double.NaN));
        assertNotSent("period", c -> c.sendHeartbeatRequest(Double.POSITIVE_INFINITY));
        assertNotSent("linearVelocity", c -> c.sendMotionRequest(new RsMotionRequest(Double.NaN, 0, 1)));
        assertNotSent("rotationalVelocity", c -> c.sendMotionRequest(new RsMotionRequest(0.5, Double.NaN, 1)));
        assertNotSent("duration", c -> c.sendMotionRequest(new RsMotionRequest(0.5, 0, Double.NEGATIVE_INFINITY)));
        assertNotSent("actuator parameter right", c -> {
            RsActuatorControlRequest r = new RsActuatorControlRequest(1, RsActuatorControlRequest.ACTIVATE);
            r.addParameter("left", 1.0);
            r.addParameter("right", Double.NaN);
            c.sendActuatorControlRequest(r);
        });
        assertNotSent("painter trailer width", c -> {
            RsBodyPainter painter = new RsBodyPainter();
            painter.setPaintColor(Color.RED);
            painter.setTrailerPosition(0.0, 0.0);
            painter.setTrailerWidth(Double.NaN);
            c.sendPainterActivationRequest(painter);
        });
    }

    @Test
    void aRefusedTimeoutDoesNotUseUpAnIndex() {
        RsClient client = clientWritingTo(new ByteArrayOutputStream());
        assertThrows(IllegalArgumentException.class, () -> client.sendTimeoutRequest(Double.NaN));
        assertEquals(1, client.sendTimeoutRequest(1.0));
    }

    @Test
    void theClientRefusesToSendABodyWithANonFiniteDimension() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        RsClient client = clientWritingTo(out);
        RsBody body = new RsBody("b");
        body.addPart(new RsBodyCircle(0.0, 0.0, Double.POSITIVE_INFINITY));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> client.sendBodySpecification(body));
        assertEquals("body part[0].radius: Infinity is not a finite number", e.getMessage());
        assertEquals(0, out.size(), "nothing was written");
    }
}
