package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.util.ArrayList;
import java.util.Arrays;
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
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsTimeoutRequest;

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
            RsBodyPart.setNextPartSerialNumber(1);
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
}
