package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.rossum.request.RsTimeoutRequest;

/** Every request an {@code RsClient} can send arrives intact at an {@code RsConnection}'s handlers. */
@Timeout(30)
class RequestRoundTripTest {

    static Link link(String transport) throws Exception {
        RsClient client = new RsClient();
        client.setLogger(QuietLog.INSTANCE);
        RsConnection connection = new RsConnection();
        switch (transport) {
            case "socket":
                return Link.socket(client, connection);
            case "direct":
                return Link.direct(client, connection);
            default:
                return Link.piped(client, connection);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void timeoutsAreNumberedFromOneAndNegativeDurationsArriveUnclamped(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            assertEquals(1, link.client.sendTimeoutRequest(1.5));
            assertEquals(2, link.client.sendTimeoutRequest(-2.0));
            RsTimeoutRequest first = (RsTimeoutRequest) server.received.next();
            assertEquals(1.5, first.timeoutDuration);
            assertEquals(1, first.timeoutIndex);
            RsTimeoutRequest second = (RsTimeoutRequest) server.received.next();
            assertEquals(2, second.timeoutIndex);
            assertEquals(-2.0, server.timeoutDuration);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void motionHaltPositionPlanAndHeartbeatRequestsArrive(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsClient c = link.client;
            c.sendMotionRequest(new RsMotionRequest(0.3, -0.2, 4.0));
            c.sendHaltRequest();
            c.sendPositionRequest();
            c.sendPlanRequest();
            c.sendHeartbeatRequest(0.1);
            c.sendHeartbeatCancellationRequest();

            RsMotionRequest m = (RsMotionRequest) server.received.next();
            assertEquals(0.3, m.linearVelocity);
            assertEquals(-0.2, m.rotationalVelocity);
            assertEquals(4.0, m.duration);
            assertInstanceOf(RsHaltRequest.class, server.received.next());
            assertEquals("position", server.received.next());
            assertInstanceOf(RsPlanRequest.class, server.received.next());
            assertEquals(0.1, ((RsHeartbeatRequest) server.received.next()).interval);
            assertEquals(0.0, ((RsHeartbeatRequest) server.received.next()).interval);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void placementNamesSurviveIncludingNoneAndRandom(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            link.client.sendPlacementRequest("home");
            link.client.sendPlacementRequest(null);
            link.client.sendPlacementRequest("");
            link.client.sendPlacementRequest("$random");
            link.client.sendPlacementRequest("caf\u00e9 \u2302");
            assertEquals("home", ((RsPlacementRequest) server.received.next()).name);
            assertNull(((RsPlacementRequest) server.received.next()).name);
            assertNull(((RsPlacementRequest) server.received.next()).name);
            assertEquals("$random", ((RsPlacementRequest) server.received.next()).name);
            assertEquals("caf\u00e9 \u2302", ((RsPlacementRequest) server.received.next()).name);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void theFiveTargetSelectionVariantsCarryTheirFlags(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsClient c = link.client;
            c.sendTargetSelectionRequest("F1", false);
            c.sendExclusiveTargetSelectionRequest("F2");
            c.sendRandomTargetSelectionRequest(false);
            c.sendExclusiveRandomTargetSelectionRequest();
            c.sendAllTargetsSelectionRequest(true);
            assertSelection(server.received.next(), false, "F1", false, false);
            assertSelection(server.received.next(), false, "F2", true, true);
            assertSelection(server.received.next(), true, "", false, false);
            assertSelection(server.received.next(), true, "", true, true);
            assertSelection(server.received.next(), false, "*", true, false);
        }
    }

    private static void assertSelection(Object o, boolean random, String name, boolean status, boolean exclusive) {
        RsTargetSelectionRequest r = (RsTargetSelectionRequest) o;
        assertEquals(random, r.random, "random");
        assertEquals(name, r.name, "name");
        assertEquals(status, r.status, "status");
        assertEquals(exclusive, r.exclusive, "exclusive");
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void actuatorParametersArriveInOrderAndAParameterlessHaltBecomesAHaltRequest(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsActuatorControlRequest r = new RsActuatorControlRequest(12, RsActuatorControlRequest.ACTIVATE);
            r.addParameter("leftRotationalVelocity", 1.25);
            r.addParameter("rightRotationalVelocity", -0.5);
            link.client.sendActuatorControlRequest(r);
            link.client.sendActuatorControlRequest(new RsActuatorControlRequest(12, RsActuatorControlRequest.HALT));
            link.client.sendActuatorControlRequest(new RsActuatorControlRequest(12, RsActuatorControlRequest.RESET));
            link.client.sendPositionRequest();

            RsActuatorControlRequest got = (RsActuatorControlRequest) server.received.next();
            assertEquals(12, got.actuatorID);
            assertEquals(RsActuatorControlRequest.ACTIVATE, got.commandID);
            assertArrayEquals(new String[] {"leftRotationalVelocity", "rightRotationalVelocity"}, got.getParameterNames());
            assertArrayEquals(new double[] {1.25, -0.5}, got.getParameterValues());
            assertInstanceOf(RsHaltRequest.class, server.received.next());
            assertEquals("position", server.received.next(), "a parameterless RESET sends nothing");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void encoderRequestsAreNumberedSeparatelyFromTimeouts(String transport) throws Exception {
        try (Link link = link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsClient c = link.client;
            RsEncoder left = () -> 3;
            RsEncoder right = () -> 4;
            assertEquals(1, c.sendTimeoutRequest(1.0));
            assertEquals(1, c.sendEncoderStatusRequest(new RsEncoder[] {left, right}, true));
            assertEquals(2, c.sendEncoderStatusRequest(right, false));
            assertEquals(-1, c.sendEncoderStatusRequest(new RsEncoder[] {left, null}, false));
            assertEquals(-1, c.sendEncoderStatusRequest((RsEncoder[]) null, false));

            server.received.next();
            RsEncoderStatusRequest a = (RsEncoderStatusRequest) server.received.next();
            assertEquals(1, a.requestIndex);
            assertArrayEquals(new int[] {3, 4}, a.encoderID);
            assertTrue(a.clearOnReport);
            RsEncoderStatusRequest b = (RsEncoderStatusRequest) server.received.next();
            assertEquals(2, b.requestIndex);
            assertFalse(b.clearOnReport);
            assertNull(server.received.poll(Duration.ofMillis(200).toMillis()), "null encoders send nothing");
        }
    }
}
