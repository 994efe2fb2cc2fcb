package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
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
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTimeoutRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.RequestListener;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * A client connected directly (no streams) gets exactly what it would decode from the wire, and the
 * server gets exactly the requests it would decode: compared byte for byte through the codecs, for
 * every event and request type and the edge cases the wire normalises (null names, empty colour lists).
 */
@Timeout(30)
class DirectLinkTest {

    static List<RsEvent> everyEvent() {
        RsPlan plan = PlanCodecTest.everyType();
        return Arrays.asList(
                new RsContactSensorEvent(1.0, 17, true, "north wall"),
                new RsContactSensorEvent(1.1, 17, false, null),
                new RsMouseClickEvent(1.5, 1, 2, 0.25, -3.5),
                new RsPositionEvent(2.0, 1.0, 2.0, -3.0, 0.5, -0.25),
                new RsRangeSensorEvent(2.5, 9, 1.0, 2.0, 0.0, 0.0, true, 0.3, "east"),
                new RsRangeSensorEvent(2.6, 9, 1.0, 2.0, 0.0, 0.0, false, 0.0, null),
                new RsTargetSensorEvent(2.7, 11, 1.0, 2.0, 0.6, 0.8, true, 0.4, 0.1, 0.41, 0.24, "F3"),
                new RsTimeoutEvent(3.0, 7),
                new RsMotionStartedEvent(4.0, 0.3, 0.1, 2.5, 1.0, 1.5, 0.75),
                new RsMotionHaltedEvent(5.0, RsMotionHaltedEvent.HALTED_ON_COLLISION, 1.1, 1.2, 1.3, 0.799),
                new RsPlacementEvent(6.0, true, "home", 2.5, 2.5, 3.9269908169872414),
                new RsPlacementEvent(6.5, false, null, 0.0, 0.0, 0.0),
                new RsTargetSelectionEvent(7.0, "F3", false),
                new RsPlanEvent(0.0, plan),
                new RsPlanEvent(0.0, null),
                new RsPaintSensorEvent(7.5, 13, 0.5, 0.5, true, 2),
                new RsHeartbeatEvent(8.0, 3),
                new RsEncoderStatusEvent(9.0, 2, 5, -17, 40, -1, 12, 4.5, true));
    }

    private static byte[] encoded(RsEvent e) {
        WireOut out = new WireOut();
        EventCodec.encode(out, e, 0);
        return out.toByteArray();
    }

    @Test
    void everyEventIsCopiedAsTheClientWouldDecodeIt() throws Exception {
        for (RsEvent e : everyEvent()) {
            RsEvent copy = EventCodec.copy(e);
            RsEvent decoded = EventCodec.decode(WireIn.of(encoded(e))).event;
            assertSame(decoded.getClass(), copy.getClass(), e.toString());
            assertEquals(decoded.getIndex(), copy.getIndex(), e.toString());
            assertEquals(decoded.simTime, copy.simTime, e.toString());
            assertArrayEquals(encoded(decoded), encoded(copy), e.toString());
        }
        RsPlanEvent plan = (RsPlanEvent) EventCodec.copy(everyEvent().get(13));
        assertEquals(0, ((RsPlan) plan.plan).getPaintArray()[0].getRegion(),
                "the wire does not carry region codes, so neither does the direct link");
        assertEquals("", ((RsContactSensorEvent) EventCodec.copy(everyEvent().get(1))).getNameOfObjectDetected());
    }

    @Test
    void aDirectlyConnectedClientsHandlersRunOnTheSendingThread() throws Exception {
        RsClient client = ClientEventLoopTest.quietClient();
        RsConnection server = new RsConnection();
        server.connectDirect(client, t -> {
            throw new AssertionError(t);
        });
        AtomicReference<Thread> handlerThread = new AtomicReference<>();
        client.addHeartbeatEventHandler(e -> handlerThread.set(Thread.currentThread()));
        server.sendHeartbeatEvent(2.5, 1);
        assertSame(Thread.currentThread(), handlerThread.get(), "delivered before sendEvent returns");
        assertEquals(2.5, client.getSimTime());
    }

    @Test
    void anEventObjectSentToSeveralClientsIsNotShared() throws Exception {
        RsConnection a = new RsConnection();
        RsConnection b = new RsConnection();
        AtomicReference<RsEvent> first = new AtomicReference<>();
        RsClient ca = ClientEventLoopTest.quietClient();
        ca.addTimeoutEventHandler(e -> {
            first.set(e);
            e.consume();
        });
        RsClient cb = ClientEventLoopTest.quietClient();
        ClientRecorder other = new ClientRecorder(cb);
        a.connectDirect(ca, t -> { });
        b.connectDirect(cb, t -> { });
        RsTimeoutEvent shared = new RsTimeoutEvent(1.0, 1);
        a.sendEvent(shared);
        b.sendEvent(shared);
        RsEvent second = other.events.next();
        assertTrue(first.get().isConsumed());
        assertTrue(!second.isConsumed(), "one client consuming its copy does not consume the other's");
    }

    /** The same requests, sent directly and over pipes, reach the server identically. */
    @Test
    void everyRequestReachesTheServerAsItWouldDecodeIt() throws Exception {
        assertEquals(requestsReceived("piped"), requestsReceived("direct"));
    }

    private static List<String> requestsReceived(String transport) throws Exception {
        try (Link link = RequestRoundTripTest.link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsClient c = link.client;
            RsBody body = new RsBody("b");
            body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
            RsBodyPainter painter = new RsBodyPainter(new double[] {0, 0, 0.05, 0, 0.05, 0.05}, 3);
            painter.setTrailerPosition(-0.1, 0.0);
            painter.setTrailerWidth(0.02);
            painter.setPaintColor(new Color[] {Color.red, Color.blue});
            body.addPart(painter);
            c.sendBodySpecification(body);
            c.sendTimeoutRequest(-1.5);
            c.sendMotionRequest(new RsMotionRequest(0.3, -0.2, 4.0));
            c.sendPlacementRequest("");
            c.sendPlacementRequest(null);
            c.sendPlacementRequest("home");
            c.sendTargetSelectionRequest(null, true);
            c.sendExclusiveRandomTargetSelectionRequest();
            c.sendAllTargetsSelectionRequest(false);
            c.sendPositionRequest();
            c.sendHaltRequest();
            c.sendPlanRequest();
            c.sendHeartbeatRequest(0.25);
            c.sendHeartbeatCancellationRequest();
            c.sendPainterActivationRequest(painter);
            c.sendPainterDeactivationRequest(painter);
            c.sendPainterErasureRequest(painter);
            RsActuatorControlRequest control = new RsActuatorControlRequest(42, RsActuatorControlRequest.ACTIVATE);
            control.addParameter("left", 1.5);
            control.addParameter("right", -2.0);
            c.sendActuatorControlRequest(control);
            control.addParameter("late", 9.0);
            c.sendEncoderStatusRequest(new RsEncoder[] {new RsWheel(new double[] {0, 0, 1, 0, 1, 1}, 3, 0.0, 0.0, 0.05)}, true);
            List<String> out = new ArrayList<>();
            for (int i = 0; i < 19; i++) {
                out.add(describe(server.received.next(), server));
            }
            return out;
        }
    }

    private static String describe(Object o, ServerRecorder server) {
        if (o instanceof RsBody) {
            return "body " + Arrays.toString(BodyCodec.encode((RsBody) o));
        }
        if (o instanceof RsTimeoutRequest) {
            return "timeout " + server.timeoutDuration + " " + ((RsTimeoutRequest) o).timeoutIndex;
        }
        if (o instanceof RsRequest) {
            return o.getClass().getSimpleName() + " " + Arrays.toString(RequestCodec.encode((RsRequest) o).toByteArray());
        }
        return String.valueOf(o);
    }

    /** Request objects as callers build them, including what the wire normalises or cannot carry. */
    private static List<RsRequest> requestsAsCallersBuildThem() {
        RsActuatorControlRequest control = new RsActuatorControlRequest(42, RsActuatorControlRequest.ACTIVATE);
        control.addParameter("left", 1.5);
        control.addParameter(null, -2.0);
        return Arrays.asList(
                new RsSubscriptionRequest(3, 17, true),
                new RsSensorRequest(9),
                new RsMotionRequest(0.3, -0.2, 4.0) {
                    private static final long serialVersionUID = 1L;
                },
                new RsHaltRequest(),
                new RsPlacementRequest(""),
                new RsPlacementRequest(null),
                new RsPlacementRequest("home"),
                new RsTargetSelectionRequest(false, null, true, false),
                new RsTargetSelectionRequest(true, "F3", false, true),
                new RsPlanRequest(),
                new RsHeartbeatRequest(0.25),
                new RsPainterChangeRequest(5, true, false, false, 0.0, 0.0, 0.0, null),
                new RsPainterChangeRequest(5, false, false, false, 0.0, 0.0, 0.0, null),
                new RsPainterChangeRequest(5, false, true, false, -0.1, 0.2, 0.02,
                        new Color[] {new Color(10, 20, 30, 100), null, Color.blue}),
                new RsPainterChangeRequest(5, false, true, true, -0.1, 0.2, 0.02, new Color[0]),
                new RsPainterChangeRequest(5, false, true, true, -0.1, 0.2, 0.02, null),
                control,
                new RsActuatorControlRequest(7, RsActuatorControlRequest.RESET),
                new RsEncoderStatusRequest(3, new int[] {4, 8}, true));
    }

    /** Hands {@code r} to the sink method for its type, as RsClient does. */
    private static void hand(RequestListener sink, RsRequest r) {
        switch (r.requestID) {
            case RsRequest.REQ_SUBSCRIPTION:
                sink.subscription((RsSubscriptionRequest) r);
                break;
            case RsRequest.REQ_SENSOR_STATUS:
                sink.sensorStatus((RsSensorRequest) r);
                break;
            case RsRequest.REQ_MOTION:
                sink.motion((RsMotionRequest) r);
                break;
            case RsRequest.REQ_HALT:
                sink.halt((RsHaltRequest) r);
                break;
            case RsRequest.REQ_PLACEMENT:
                sink.placement((RsPlacementRequest) r);
                break;
            case RsRequest.REQ_TARGET_SELECTION:
                sink.targetSelection((RsTargetSelectionRequest) r);
                break;
            case RsRequest.REQ_PLAN:
                sink.plan((RsPlanRequest) r);
                break;
            case RsRequest.REQ_HEARTBEAT:
                sink.heartbeat((RsHeartbeatRequest) r);
                break;
            case RsRequest.REQ_PAINTER_CHANGE:
                sink.painterChange((RsPainterChangeRequest) r);
                break;
            case RsRequest.REQ_ACTUATOR_CONTROL:
                sink.actuatorControl((RsActuatorControlRequest) r);
                break;
            default:
                sink.encoderStatus((RsEncoderStatusRequest) r);
                break;
        }
    }

    /** Every instance field a handler can see, colours with their alpha; the class exactly. */
    private static String fields(RsRequest r) throws Exception {
        StringBuilder b = new StringBuilder(r.getClass().getName());
        Field[] fields = r.getClass().getFields();
        Arrays.sort(fields, Comparator.comparing(Field::getName));
        for (Field f : fields) {
            if (Modifier.isStatic(f.getModifiers())) {
                continue;
            }
            Object v = f.get(r);
            b.append(' ').append(f.getName()).append('=');
            if (v instanceof Color[]) {
                List<String> colors = new ArrayList<>();
                for (Color c : (Color[]) v) {
                    colors.add(c == null ? "null" : c.getClass().getName() + Integer.toHexString(c.getRGB()));
                }
                b.append(colors);
            } else if (v instanceof int[]) {
                b.append(Arrays.toString((int[]) v));
            } else {
                b.append(v == null ? "null" : "\"" + v + "\"");
            }
        }
        if (r instanceof RsActuatorControlRequest) {
            RsActuatorControlRequest a = (RsActuatorControlRequest) r;
            b.append(' ').append(Arrays.toString(a.getParameterNames())).append(Arrays.toString(a.getParameterValues()));
        }
        return b.toString();
    }

    /** The direct link's copies are what decoding gives, field by field, not just byte for byte. */
    @Test
    void theDirectLinksRequestCopiesAreWhatDecodingGives() throws Exception {
        for (RsRequest r : requestsAsCallersBuildThem()) {
            RecordingSink decoded = new RecordingSink();
            RequestCodec.decode(WireIn.of(RequestCodec.encode(r).toByteArray()), decoded);
            RecordingSink copied = new RecordingSink();
            hand(RequestCodec.copying(copied), r);
            assertEquals(decoded.calls, copied.calls, r.toString());
            assertEquals(fields(decoded.last), fields(copied.last), r.toString());
            assertNotSame(r, copied.last, "the caller's object does not reach the server");
        }
        RecordingSink copied = new RecordingSink();
        RequestListener copying = RequestCodec.copying(copied);
        copying.timeout(-1.5, 4);
        copying.position();
        copying.setPosition();
        assertEquals(Arrays.asList("timeout", "position", "setPosition"), copied.calls);
        assertEquals(-1.5, copied.timeoutDuration);
        assertEquals(4, copied.timeoutIndex);
    }

    @Test
    void theDirectLinkCopiesArraysTheCallerMayChangeLater() throws Exception {
        RecordingSink copied = new RecordingSink();
        int[] ids = {4, 8};
        RequestCodec.copying(copied).encoderStatus(new RsEncoderStatusRequest(1, ids, false));
        ids[0] = 99;
        assertArrayEquals(new int[] {4, 8}, ((RsEncoderStatusRequest) copied.last).encoderID);
        Color[] colors = {Color.red};
        RequestCodec.copying(copied).painterChange(
                new RsPainterChangeRequest(5, false, true, true, 0.0, 0.0, 0.02, colors));
        colors[0] = Color.green;
        assertEquals(Color.red, ((RsPainterChangeRequest) copied.last).color[0]);
    }

    @Test
    void aBodySentAfterADirectSessionEndedIsDroppedWithTheWirePathsLogLine() throws Exception {
        List<String> log = new ArrayList<>();
        RsClient client = new RsClient();
        client.setLogger(new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                log.add(message);
            }
        });
        client.setVerbosity(true);
        RsConnection server = new RsConnection();
        ServerRecorder recorder = new ServerRecorder(server);
        server.connectDirect(client, t -> {
            throw new AssertionError(t);
        });
        server.shutdown();
        RsBody body = new RsBody("late");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
        client.sendBodySpecification(body);
        assertNull(recorder.received.poll(0), "nothing reaches the closed server");
        assertTrue(log.contains("RsClient: session closed, BODY_SPECIFICATION not sent"), log.toString());
    }

    @Test
    void closingEitherSideOfADirectLinkClosesBothOnce() throws Exception {
        for (boolean clientFirst : new boolean[] {true, false}) {
            RsClient client = ClientEventLoopTest.quietClient();
            RsConnection server = new RsConnection();
            server.setLogger(null);
            int[] calls = new int[2];
            client.setProtocolShutdownHandler(() -> calls[0]++);
            server.setProtocolShutdownHandler(() -> calls[1]++);
            server.connectDirect(client, t -> {
                throw new AssertionError(t);
            });
            assertFalse(client.isClosed());
            if (clientFirst) {
                client.shutdown();
            } else {
                server.shutdown();
            }
            assertTrue(client.isClosed(), "client first: " + clientFirst);
            assertTrue(server.isClosed(), "client first: " + clientFirst);
            client.shutdown();
            server.shutdown();
            assertArrayEquals(new int[] {1, 1}, calls, "client first: " + clientFirst);
        }
    }
}
