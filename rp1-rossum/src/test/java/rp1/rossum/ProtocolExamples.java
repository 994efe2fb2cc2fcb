package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * The worked examples of docs/protocol.md, by name: how our code produces each message, and what
 * decoding the document's bytes must give back. Messages are produced the way a session produces
 * them: requests by {@link RsClient}'s send methods, events by {@link RsConnection#sendEvent}.
 */
final class ProtocolExamples {
    /** Produces the message an example shows. */
    interface Builder {
        byte[] build() throws Exception;
    }

    /** Decodes an example's bytes and checks the values the document describes. */
    interface Check {
        void check(byte[] message) throws Exception;
    }

    record Example(Builder builder, Check check) {
    }

    private interface ClientAction {
        void run(RsClient client) throws Exception;
    }

    private static final byte[] NOTHING = new byte[0];
    private static final double[] SQUARE = {-0.05, -0.05, 0.05, -0.05, 0.05, 0.05, -0.05, 0.05};

    private ProtocolExamples() {
    }

    /** Every example, by name. */
    static Map<String, Example> all() {
        Map<String, Example> m = new LinkedHashMap<>();
        handshake(m);
        bodies(m);
        requests(m);
        events(m);
        interlock(m);
        return m;
    }

    // ---------------------------------------------------------------------------------------------
    // Handshake and bodies

    private static void handshake(Map<String, Example> m) {
        byte[] accept = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2};
        m.put("connect", new Example(() -> {
            ByteArrayOutputStream sent = new ByteArrayOutputStream();
            RsClient client = new RsClient();
            client.setInputOutputStreams(new ByteArrayInputStream(accept), sent);
            client.exchangeIntroductions();
            return sent.toByteArray();
        }, bytes -> {
            Reader r = Reader.of(bytes);
            assertEquals(List.of(0, 0, 0, 0, RsProtocol.CONNECT), r.ints(5));
            r.assertEnd();
        }));
        m.put("accept", new Example(() -> {
            ByteArrayOutputStream sent = new ByteArrayOutputStream();
            RsConnection connection = new RsConnection();
            connection.setInputOutputStreams(new ByteArrayInputStream(build("connect")), sent);
            connection.exchangeIntroductions();
            return sent.toByteArray();
        }, bytes -> {
            Reader r = Reader.of(bytes);
            assertEquals(List.of(0, 0, 0, 1, RsProtocol.ACCEPT), r.ints(5));
            r.assertEnd();
        }));
    }

    private static void bodies(Map<String, Example> m) {
        m.put("body-circle", new Example(() -> fromClient(2, c -> c.sendBodySpecification(circleBody())), bytes -> {
            assertEquals(114, bytes.length);
            RsBody body = body(bytes);
            assertEquals("B", body.getName());
            RsBodyCircle circle = (RsBodyCircle) body.getPartByID(1);
            assertEquals("c", circle.getName());
            assertEquals(0.15, circle.refRadius);
            assertEquals(Color.white, circle.getColdFillColor());
            assertNull(circle.getColdLineColor());
        }));
        m.put("body-differential", new Example(() -> fromClient(2, c -> c.sendBodySpecification(wheeledBody())), bytes -> {
            RsBody body = body(bytes);
            RsWheelSystem steering = assertInstanceOf(RsDifferentialSteering.class, body.getPartByID(1));
            assertEquals(0.4, steering.getTrackWidth());
            assertEquals(0.05, steering.getDriveWheelRadius());
            RsWheel[] wheels = steering.getWheels();
            assertEquals(2, wheels.length);
            assertEquals(2, wheels[0].getID());
            assertEquals(3, wheels[1].getID());
            assertEquals(0.2, wheels[0].getY());
            assertEquals(64, wheels[1].getEncoderIntervalCount());
        }));
        m.put("body-range-sensor", new Example(() -> fromClient(2, c -> c.sendBodySpecification(rangeSensorBody())),
                bytes -> {
                    RsBodyRangeSensor s = (RsBodyRangeSensor) body(bytes).getPartByID(4);
                    assertEquals("sonar", s.getName());
                    assertArrayEquals(new double[] {0, -0.05, 0.1, 0, 0, 0.05}, s.getOutlineVertices());
                    assertEquals(0.1, s.getXDetector());
                    assertEquals(2.0, s.getMaxRange());
                    assertEquals(8, s.getNRangeBin());
                    assertEquals(Color.red, s.getHotLineColor());
                }));
    }

    /** The body of the classic 114-byte example: one circle, the body's first part. */
    private static RsBody circleBody() {
        RsBody body = new RsBody("B");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.15);
        c.setName("c");
        c.setFillColor(Color.white);
        c.setLineColor(null);
        body.addPart(c);
        return body;
    }

    private static RsDifferentialSteering steering() {
        RsDifferentialSteering steering = new RsDifferentialSteering(0.4, 0.05);
        steering.addDefaultWheels(0.05, 0.02);
        steering.addEncodersToDefaultWheels(64);
        return steering;
    }

    private static RsBody wheeledBody() {
        RsBody body = new RsBody("W");
        body.addPart(steering());
        return body;
    }

    private static RsBody rangeSensorBody() {
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(new double[] {0, -0.05, 0.1, 0, 0, 0.05}, 3, 0.1, 0, 0, 2.0, 8);
        sonar.assignID(4);
        sonar.setName("sonar");
        RsBody body = new RsBody("R");
        body.addPart(sonar);
        return body;
    }

    private static RsBody body(byte[] message) throws Exception {
        Reader r = Reader.payload(message, RsProtocol.BODY_SPECIFICATION);
        RsBody body = BodyCodec.decode(r.in);
        r.assertEnd();
        return body;
    }

    // ---------------------------------------------------------------------------------------------
    // Requests

    private static void requests(Map<String, Example> m) {
        m.put("request-timeout", new Example(() -> fromClient(3, c -> c.sendTimeoutRequest(1.5)), bytes -> {
            RecordingSink s = request(bytes);
            assertEquals(1.5, s.timeoutDuration);
            assertEquals(1, s.timeoutIndex);
        }));
        m.put("request-subscription", new Example(
                () -> fromClient(4, c -> c.addTargetSensorEventHandler(targetSensor(), e -> { })), bytes -> {
                    RsSubscriptionRequest r = (RsSubscriptionRequest) request(bytes).last;
                    assertEquals(RsEvent.EVT_TARGET_SENSOR, r.eventCode);
                    assertEquals(5, r.eventIndex);
                    assertTrue(r.eventEnable);
                }));
        m.put("request-sensor-status", new Example(() -> fromClient(5, c -> c.sendSensorStatusRequest(targetSensor())),
                bytes -> assertEquals(5, ((RsSensorRequest) request(bytes).last).sensorID)));
        m.put("request-motion", new Example(
                () -> fromClient(6, c -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.25, 2.0))), bytes -> {
                    RsMotionRequest r = (RsMotionRequest) request(bytes).last;
                    assertEquals(0.5, r.linearVelocity);
                    assertEquals(0.25, r.rotationalVelocity);
                    assertEquals(2.0, r.duration);
                }));
        m.put("request-halt", new Example(() -> fromClient(7, RsClient::sendHaltRequest),
                bytes -> assertEquals(List.of("halt"), request(bytes).calls)));
        m.put("request-position", new Example(() -> fromClient(8, RsClient::sendPositionRequest),
                bytes -> assertEquals(List.of("position"), request(bytes).calls)));
        m.put("request-set-position", new Example(
                () -> new WireOut().header(0, 0, 9, RsProtocol.REQUEST).i32(6).i32(0).toByteArray(),
                bytes -> assertEquals(List.of("setPosition"), request(bytes).calls)));
        m.put("request-placement", new Example(() -> fromClient(10, c -> c.sendPlacementRequest("home")), bytes -> {
            assertEquals(38, bytes.length);
            assertEquals("home", ((RsPlacementRequest) request(bytes).last).name);
        }));
        m.put("request-placement-any", new Example(() -> fromClient(11, c -> c.sendPlacementRequest(null)), bytes -> {
            assertEquals(32, bytes.length);
            assertNull(((RsPlacementRequest) request(bytes).last).name);
        }));
        m.put("request-target-selection", new Example(
                () -> fromClient(12, c -> c.sendExclusiveTargetSelectionRequest("candle")), bytes -> {
                    RsTargetSelectionRequest r = (RsTargetSelectionRequest) request(bytes).last;
                    assertFalse(r.random);
                    assertEquals("candle", r.name);
                    assertTrue(r.status);
                    assertTrue(r.exclusive);
                }));
        m.put("request-plan", new Example(() -> fromClient(13, RsClient::sendPlanRequest),
                bytes -> assertEquals(List.of("plan"), request(bytes).calls)));
        m.put("request-heartbeat", new Example(() -> fromClient(14, c -> c.sendHeartbeatRequest(0.5)),
                bytes -> assertEquals(0.5, ((RsHeartbeatRequest) request(bytes).last).interval)));
        painterRequests(m);
        m.put("request-actuator-control", new Example(
                () -> fromClient(18, c -> c.sendActuatorControlRequest(steering().getControlRequestForWheelRotation(2.0, 4.0))),
                bytes -> {
                    RsActuatorControlRequest r = (RsActuatorControlRequest) request(bytes).last;
                    assertEquals(1, r.actuatorID);
                    assertEquals(RsActuatorControlRequest.ACTIVATE, r.commandID);
                    assertArrayEquals(new String[] {"leftRotationalVelocity", "rightRotationalVelocity"}, r.getParameterNames());
                    assertArrayEquals(new double[] {2.0, 4.0}, r.getParameterValues());
                }));
        m.put("request-encoder-status", new Example(() -> fromClient(19, c -> {
            RsEncoder[] encoders = steering().addEncodersToDefaultWheels(64);
            c.sendEncoderStatusRequest(encoders, true);
        }), bytes -> {
            RsEncoderStatusRequest r = (RsEncoderStatusRequest) request(bytes).last;
            assertEquals(1, r.requestIndex);
            assertArrayEquals(new int[] {2, 3}, r.encoderID);
            assertTrue(r.clearOnReport);
        }));
    }

    private static void painterRequests(Map<String, Example> m) {
        m.put("request-painter-activation", new Example(() -> fromClient(15, c -> c.sendPainterActivationRequest(painter())),
                bytes -> {
                    RsPainterChangeRequest r = (RsPainterChangeRequest) request(bytes).last;
                    assertEquals(7, r.painterID);
                    assertTrue(r.activation);
                    assertEquals(-0.25, r.xTrailer);
                    assertEquals(0.0625, r.wTrailer);
                    assertArrayEquals(new Color[] {Color.red}, r.color);
                }));
        m.put("request-painter-deactivation", new Example(
                () -> fromClient(16, c -> c.sendPainterDeactivationRequest(painter())), bytes -> {
                    RsPainterChangeRequest r = (RsPainterChangeRequest) request(bytes).last;
                    assertEquals(7, r.painterID);
                    assertFalse(r.erasure);
                    assertFalse(r.activation);
                }));
        m.put("request-painter-erasure", new Example(() -> fromClient(17, c -> c.sendPainterErasureRequest(painter())),
                bytes -> {
                    RsPainterChangeRequest r = (RsPainterChangeRequest) request(bytes).last;
                    assertEquals(7, r.painterID);
                    assertTrue(r.erasure);
                }));
    }

    private static RsBodyTargetSensor targetSensor() {
        RsBodyTargetSensor sensor = new RsBodyTargetSensor(SQUARE, 4, 0.05, 0, 0, 0.5, 3.0, 4, 4);
        sensor.assignID(5);
        return sensor;
    }

    private static RsBodyPainter painter() {
        RsBodyPainter p = new RsBodyPainter(SQUARE, 4);
        p.assignID(7);
        p.setTrailerPosition(-0.25, 0);
        p.setTrailerWidth(0.0625);
        p.setPaintColor(Color.red);
        return p;
    }

    /** Decodes a REQUEST message completely. */
    private static RecordingSink request(byte[] message) throws Exception {
        Reader r = Reader.payload(message, RsProtocol.REQUEST);
        RecordingSink sink = new RecordingSink();
        RequestCodec.decode(r.in, sink);
        r.assertEnd();
        assertEquals(1, sink.calls.size());
        return sink;
    }

    // ---------------------------------------------------------------------------------------------
    // Events

    private static void events(Map<String, Example> m) {
        event(m, "event-contact-sensor", 2, new RsContactSensorEvent(3.25, 6, true, "north"), e -> {
            RsContactSensorEvent c = (RsContactSensorEvent) e;
            assertEquals(6, c.sensorID);
            assertTrue(c.status);
            assertEquals("north", c.getNameOfObjectDetected());
        });
        event(m, "event-mouse-click", 3, new RsMouseClickEvent(4.0, 1, 2, 1.5, 2.25), e -> {
            RsMouseClickEvent c = (RsMouseClickEvent) e;
            assertEquals(1, c.button);
            assertEquals(2, c.clickCount);
            assertEquals(2.25, c.y);
        });
        event(m, "event-position", 4, new RsPositionEvent(5.0, 1.0, 2.0, 0.5, 0.25, -0.125), e -> {
            RsPositionEvent p = (RsPositionEvent) e;
            assertEquals(2.0, p.y);
            assertEquals(-0.125, p.turnRate);
        });
        event(m, "event-range-sensor", 5, new RsRangeSensorEvent(5.5, 4, 1.0, 2.0, 0, 0, true, 0.75, "north"), e -> {
            RsRangeSensorEvent r = (RsRangeSensorEvent) e;
            assertEquals(4, r.sensorID);
            assertTrue(r.status);
            assertEquals(0.75, r.range);
        });
        event(m, "event-target-sensor", 6,
                new RsTargetSensorEvent(6.0, 5, 1.0, 2.0, 1.0, 0.0, true, 1.5, 0.0, 1.5, 0.0, "candle"), e -> {
                    RsTargetSensorEvent t = (RsTargetSensorEvent) e;
                    assertEquals(5, t.sensorID);
                    assertEquals(1.0, t.ux);
                    assertEquals(1.5, t.range);
                    assertEquals("candle", t.getNameOfObjectDetected());
                });
        event(m, "event-timeout", 5, new RsTimeoutEvent(2.5, 1), e -> {
            assertEquals(2.5, e.simTime);
            assertEquals(1, ((RsTimeoutEvent) e).timeoutIndex);
        });
        event(m, "event-motion-started", 7, new RsMotionStartedEvent(6.5, 0.5, 0.25, 2.0, 1.0, 2.0, 0.5), e -> {
            RsMotionStartedEvent s = (RsMotionStartedEvent) e;
            assertEquals(0.25, s.rotationalVelocity);
            assertEquals(2.0, s.duration);
        });
        event(m, "event-motion-halted", 8, new RsMotionHaltedEvent(8.5, RsMotionHaltedEvent.HALTED_ON_COLLISION,
                1.75, 2.5, 1.0, 2.0), e -> {
                    RsMotionHaltedEvent h = (RsMotionHaltedEvent) e;
                    assertEquals("collision", h.whyHalted());
                    assertEquals(2.0, h.duration);
                });
        event(m, "event-placement", 6, new RsPlacementEvent(1.25, true, "home", 2.5, 2.5, 225 * Math.PI / 180), e -> {
            RsPlacementEvent p = (RsPlacementEvent) e;
            assertTrue(p.valid);
            assertEquals("home", p.name);
            assertEquals(3.9269908169872414, p.orientation);
        });
        event(m, "event-target-selection", 9, new RsTargetSelectionEvent(9.0, "candle", false), e -> {
            RsTargetSelectionEvent t = (RsTargetSelectionEvent) e;
            assertEquals("candle", t.targetName);
            assertFalse(t.status);
        });
        event(m, "event-plan", 2, new RsPlanEvent(0.0, plan()), e -> checkPlan((RsPlan) ((RsPlanEvent) e).plan));
        event(m, "event-paint-sensor", 10, new RsPaintSensorEvent(10.0, 9, 0.5, 0.125, true, 3), e -> {
            RsPaintSensorEvent p = (RsPaintSensorEvent) e;
            assertEquals(9, p.sensorID);
            assertTrue(p.status);
            assertEquals(3, p.region);
        });
        event(m, "event-heartbeat", 11, new RsHeartbeatEvent(10.5, 3),
                e -> assertEquals(3, ((RsHeartbeatEvent) e).sequence));
        event(m, "event-encoder-status", 12, new RsEncoderStatusEvent(11.0, 1, 2, 5, 7, 1, 5, 1.5, true), e -> {
            RsEncoderStatusEvent s = (RsEncoderStatusEvent) e;
            assertEquals(2, s.encoderID);
            assertEquals(5, s.accumulatorValue);
            assertEquals(7, s.absoluteAccumulatorValue);
            assertEquals(1.5, s.encoderAngle);
            assertTrue(s.clearOnReport);
        });
    }

    private interface EventCheck {
        void check(RsEvent decoded) throws Exception;
    }

    /** An event without interlock, sent by a connection whose last message had {@code sequence - 1}. */
    private static void event(Map<String, Example> m, String name, int sequence, RsEvent event, EventCheck check) {
        m.put(name, new Example(() -> fromServer(sequence, 0, event), bytes -> {
            EventCodec.Decoded d = decodeEvent(bytes);
            assertEquals(0, d.interlock);
            assertEquals(event.eventID, d.event.eventID);
            check.check(d.event);
        }));
    }

    /** A plan with one object of every kind. */
    private static RsPlan plan() {
        RsPlan plan = new RsPlan();
        plan.setCaption("demo");
        add(plan, new RsWall("north", plan), 0, 2, 2, 2, 2, 2.5, 0, 2.5);
        add(plan, new RsTarget("candle", plan), 1.5, 1, 0.125);
        add(plan, new RsPlacement("home", plan), 0.5, 0.5, 0, 0.25);
        RsNavNode a = (RsNavNode) add(plan, new RsNavNode("a", plan), 0.5, 1.5);
        RsNavNode b = (RsNavNode) add(plan, new RsNavNode("b", plan), 1.5, 1.5);
        b.setLabel("B");
        RsNavLink link = new RsNavLink("ab", plan);
        link.setNodes(a, b);
        a.addLink(link);
        b.addLink(link);
        plan.addObject(link);
        RsObject paint = add(plan, new RsPaint("stripe", plan), 0, 0, 1, 0, 1, 0.25, 0, 0.25);
        paint.setFillColor(Color.yellow);
        return plan;
    }

    private static RsObject add(RsPlan plan, RsObject o, double... geometry) {
        o.setGeometry(geometry);
        plan.addObject(o);
        return o;
    }

    private static void checkPlan(RsPlan plan) {
        assertEquals("demo", plan.getCaption());
        assertEquals(7, plan.getObjectCount());
        assertArrayEquals(new double[] {0, 2, 2, 2, 2, 2.5, 0, 2.5}, plan.getWallArray()[0].getGeometry());
        assertArrayEquals(new double[] {1.5, 1, 0.125}, plan.getTargetArray()[0].getGeometry());
        assertEquals(0.25, plan.getPlacementArray()[0].radius);
        RsNavLink link = plan.getNavLinkArray()[0];
        assertEquals("a", link.n0.getName());
        assertEquals("B", link.n1.getLabel());
        RsPaint paint = plan.getPaintArray()[0];
        assertEquals(Color.yellow, paint.fillColor);
        assertEquals(10, paint.getGeometry().length);
    }

    private static EventCodec.Decoded decodeEvent(byte[] message) throws Exception {
        Reader r = Reader.payload(message, RsProtocol.EVENT);
        EventCodec.Decoded d = EventCodec.decode(r.in);
        r.assertEnd();
        return d;
    }

    // ---------------------------------------------------------------------------------------------
    // Interlock

    private static void interlock(Map<String, Example> m) {
        m.put("event-timeout-interlocked", new Example(() -> fromServer(7, 7, new RsTimeoutEvent(3.0, 2)), bytes -> {
            EventCodec.Decoded d = decodeEvent(bytes);
            assertEquals(7, d.interlock);
            assertEquals(2, ((RsTimeoutEvent) d.event).timeoutIndex);
        }));
        m.put("interlock-ack", new Example(() -> {
            ByteArrayOutputStream sent = new ByteArrayOutputStream();
            RsClient client = new RsClient();
            client.setInputOutputStreams(new ByteArrayInputStream(build("event-timeout-interlocked")), sent);
            client.sequence = 19;
            client.setLogger(new BadInputTest.ListLogger(new ArrayList<>()));
            client.run();
            return sent.toByteArray();
        }, bytes -> {
            FixedInterlock interlock = new FixedInterlock(7);
            RsConnection connection = new RsConnection();
            connection.setInputOutputStreams(new ByteArrayInputStream(bytes), new ByteArrayOutputStream());
            connection.addInterlock(interlock);
            connection.run();
            assertEquals(List.of(7), interlock.closed);
        }));
    }

    /** An interlock that always hands out the same number and records acknowledgements. */
    private static final class FixedInterlock implements RsInterlock {
        private final int value;
        final List<Integer> closed = Collections.synchronizedList(new ArrayList<>());

        FixedInterlock(int value) {
            this.value = value;
        }

        @Override
        public int openInterlock() {
            return value;
        }

        @Override
        public boolean closeInterlock(int interlock) {
            closed.add(interlock);
            return interlock >= value;
        }

        @Override
        public int getMaximumInterlockIndex() {
            return value;
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Producing and reading messages

    private static byte[] build(String name) throws Exception {
        return all().get(name).builder().build();
    }

    /** What a client sends when its previous message carried {@code sequence - 1}. */
    private static byte[] fromClient(int sequence, ClientAction action) throws Exception {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = new RsClient();
        client.setInputOutputStreams(new ByteArrayInputStream(NOTHING), sent);
        client.sequence = sequence - 1;
        action.run(client);
        return sent.toByteArray();
    }

    /** What a connection sends, with the interlock on if {@code interlock} is positive. */
    private static byte[] fromServer(int sequence, int interlock, RsEvent event) {
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsConnection connection = new RsConnection();
        connection.setInputOutputStreams(new ByteArrayInputStream(NOTHING), sent);
        connection.sequence = sequence - 1;
        if (interlock > 0) {
            connection.addInterlock(new FixedInterlock(interlock));
        }
        connection.sendEvent(event);
        return sent.toByteArray();
    }

    /** A reader over a message that can tell whether every byte was used. */
    private static final class Reader {
        final WireIn in;
        private final ByteArrayInputStream bytes;

        private Reader(byte[] message) {
            bytes = new ByteArrayInputStream(message);
            in = new WireIn(new DataInputStream(bytes));
        }

        static Reader of(byte[] message) {
            return new Reader(message);
        }

        /** Checks the header (version 0, client id and key 0, {@code code}) and stands after it. */
        static Reader payload(byte[] message, int code) throws Exception {
            Reader r = new Reader(message);
            List<Integer> header = r.ints(5);
            assertEquals(Arrays.asList(0, 0, 0), header.subList(0, 3), "version, client id, client key");
            assertEquals(code, header.get(4), "transaction code");
            return r;
        }

        List<Integer> ints(int n) throws Exception {
            Integer[] values = new Integer[n];
            for (int i = 0; i < n; i++) {
                values[i] = in.i32("int " + i);
            }
            return Arrays.asList(values);
        }

        void assertEnd() {
            assertEquals(0, bytes.available(), "bytes left over after decoding");
        }
    }
}
