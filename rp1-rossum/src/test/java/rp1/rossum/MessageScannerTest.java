package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.wire.MessageScanner;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireOut;

/**
 * The scanner that finds where a client's message ends as its bytes arrive: it agrees with the
 * encoders on every message a server receives, passes over each byte once however the message is cut,
 * and ends a message at a value the decoder refuses.
 */
@Timeout(60)
class MessageScannerTest {
    private static final double[] TRIANGLE = {0, -0.05, 0.1, 0, 0, 0.05};

    private static byte[] message(int code, WireOut payload) throws Exception {
        return message(code, payload.toByteArray());
    }

    private static byte[] message(int code, byte[] payload) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        new WireOut().header(0, 0, 1, code).writeTo(b);
        b.write(payload);
        return b.toByteArray();
    }

    private static byte[] request(WireOut r) throws Exception {
        return message(RsProtocol.REQUEST, r);
    }

    private static RsBody everyPart() {
        RsBody body = new RsBody("all");
        RsDifferentialSteering differential = new RsDifferentialSteering(0.4, 0.05);
        differential.addDefaultWheels(0.05, 0.02);
        differential.addEncodersToDefaultWheels(64);
        body.addPart(differential);
        RsAckermanSteering ackerman = new RsAckermanSteering(0.4, 0.5, 0.05, 0.5, true);
        body.addPart(ackerman);
        RsBodyCircle circle = new RsBodyCircle(0, 0, 0.15);
        circle.setName("circle");
        circle.setLineColor(null);
        body.addPart(circle);
        body.addPart(new RsBodyShape(TRIANGLE, 3));
        body.addPart(new RsBodyTargetSensor(TRIANGLE, 3, 0.1, 0, 0.5, 0.2, 3.0, 4, 8));
        body.addPart(new RsBodyContactSensor(TRIANGLE, 3));
        body.addPart(new RsBodyRangeSensor(TRIANGLE, 3, 0.1, 0, 0, 2.0, 8));
        RsBodyPaintSensor paint = new RsBodyPaintSensor(TRIANGLE, 3, 0.0, 0.0);
        paint.setRegionSensitivity(new int[] {1, 2, 3});
        body.addPart(paint);
        body.addPart(new RsBodyPainter(TRIANGLE, 3));
        return body;
    }

    /** One of every message a server receives, each as a client's encoder writes it. */
    private static List<byte[]> everyMessage() throws Exception {
        RsActuatorControlRequest actuator = new RsActuatorControlRequest(3, 1);
        actuator.addParameter("speed", 0.5);
        actuator.addParameter("", 2.0);
        return List.of(
                new WireOut().header(0, 0, 1, RsProtocol.CONNECT).toByteArray(),
                request(RequestCodec.timeout(1.5, 7)),
                request(RequestCodec.subscription(3, 9, true)),
                request(RequestCodec.sensorStatus(4)),
                request(RequestCodec.motion(new RsMotionRequest(0.5, 0.25, 3.0))),
                request(RequestCodec.halt()),
                request(RequestCodec.position()),
                request(RequestCodec.placement(null)),
                request(RequestCodec.placement("home")),
                request(RequestCodec.targetSelection(false, "F1", true, false)),
                request(RequestCodec.plan()),
                request(RequestCodec.heartbeat(0.25)),
                request(RequestCodec.painterErasure(2)),
                request(RequestCodec.painterDeactivation(2)),
                request(RequestCodec.painterActivation(2, 0.1, 0.2, 0.05, new Color[] {Color.red, null, Color.blue})),
                request(RequestCodec.actuatorControl(actuator)),
                request(RequestCodec.encoderStatus(5, new int[] {1, 2, 3}, true)),
                message(RsProtocol.BODY_SPECIFICATION, BodyCodec.encode(everyPart())),
                message(RsProtocol.INTERLOCK, new WireOut().i32(12)));
    }

    @Test
    void everyMessageEndsWhereItsEncodingEndsHoweverItArrives() throws Exception {
        List<byte[]> messages = everyMessage();
        for (int m = 0; m < messages.size(); m++) {
            byte[] b = messages.get(m);
            boolean introduced = m > 0;
            assertEquals(b.length, new MessageScanner().scan(b, 0, b.length, introduced), "message " + m + " whole");
            MessageScanner scanner = new MessageScanner();
            for (int end = 0; end < b.length; end++) {
                assertEquals(-1, scanner.scan(b, 0, end, introduced), "message " + m + " cut at " + end);
                assertTrue(end - scanner.scanned() < 4,
                        "message " + m + " cut at " + end + ": all but the start of one value is passed over at once");
            }
            assertEquals(b.length, scanner.scan(b, 0, b.length, introduced), "message " + m + " byte by byte");
            assertEquals(0, scanner.scanned(), "ready for the next message");
        }
    }

    @Test
    void messagesFollowingEachOtherAreFoundOneAfterTheOther() throws Exception {
        List<byte[]> messages = everyMessage().subList(1, everyMessage().size());
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        for (byte[] m : messages) {
            all.write(m);
        }
        byte[] b = all.toByteArray();
        MessageScanner scanner = new MessageScanner();
        List<Integer> lengths = new ArrayList<>();
        int at = 0;
        while (at < b.length) {
            int n = scanner.scan(b, at, b.length, true);
            lengths.add(n);
            at += n;
        }
        List<Integer> expected = new ArrayList<>();
        messages.forEach(m -> expected.add(m.length));
        assertEquals(expected, lengths);
    }

    @Test
    void aValueTheDecoderRefusesEndsTheMessageThere() throws Exception {
        byte[] unknownCode = new WireOut().header(0, 0, 1, 99).i32(0).toByteArray();
        assertEquals(20, new MessageScanner().scan(unknownCode, 0, unknownCode.length, true));
        byte[] hugeCount = message(RsProtocol.BODY_SPECIFICATION, new WireOut().str("x").i32(1 << 30));
        assertEquals(hugeCount.length, new MessageScanner().scan(hugeCount, 0, hugeCount.length, true));
        byte[] badColour = request(new WireOut().i32(11).i32(0).i32(1).bool(false).bool(true).bool(true)
                .f64(0).f64(0).f64(0).i32(1).i32(1).i32(300).i32(0).i32(0));
        assertEquals(badColour.length - 8, new MessageScanner().scan(badColour, 0, badColour.length, true));
        byte[] wrongVersion = new WireOut().i32(7).i32(0).toByteArray();
        assertEquals(4, new MessageScanner().scan(wrongVersion, 0, wrongVersion.length, false));
    }

    /**
     * A large body trickling in a kilobyte at a time: each arrival is scanned from where the last one
     * stopped, and the body is decoded once, when its last byte comes.
     */
    @Test
    void aBodyTricklingInIsDecodedOnceWhenItIsWhole() throws Exception {
        RsBody big = new RsBody("big");
        double[] outline = new double[2 * 20000];
        for (int i = 0; i < 20000; i++) {
            outline[2 * i] = Math.cos(i);
            outline[2 * i + 1] = Math.sin(i);
        }
        for (int k = 0; k < 8; k++) {
            big.addPart(new RsBodyShape(outline, 20000));
        }
        byte[] connect = new WireOut().header(0, 0, 1, RsProtocol.CONNECT).toByteArray();
        byte[] body = message(RsProtocol.BODY_SPECIFICATION, BodyCodec.encode(big));
        RsConnection c = new RsConnection();
        c.setLogger(null);
        c.setInputOutputStreams(null, new ByteArrayOutputStream());
        int[] bodies = {0};
        c.setBodyHandler(new RsConnectionBodyHandler() {
            @Override
            public void process(RsBody b) {
                bodies[0]++;
            }
        });
        c.receive(connect, 0, connect.length);
        for (int at = 0; at < body.length; at += 1024) {
            int n = Math.min(1024, body.length - at);
            c.receive(body, at, n);
            assertEquals(at + n < body.length ? at + n : 0, c.getIncompleteMessageBytes());
        }
        assertEquals(1, bodies[0]);
    }
}
