package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTimeoutEvent;

/** Every non-sensor event an {@code RsConnection} sends reaches the client's handlers with its fields intact. */
@Timeout(30)
class EventRoundTripTest {

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void everyNonSensorEventArrivesIntact(String transport) throws Exception {
        try (Link link = RequestRoundTripTest.link(transport)) {
            ClientRecorder client = new ClientRecorder(link.client);
            link.startServer().startClientLoop();
            RsConnection s = link.connection;
            s.sendMouseClickEvent(new RsMouseClickEvent(1.5, 1, 2, 0.25, -3.5));
            s.sendPositionEvent(new RsPositionEvent(2.0, 1.0, 2.0, -3.0, 0.5, -0.25));
            s.sendTimeoutEvent(new RsTimeoutEvent(3.0, 7));
            s.sendMotionStartedEvent(new RsMotionStartedEvent(4.0, 0.3, 0.1, 2.5, 1.0, 1.5, 0.75));
            s.sendMotionHaltedEvent(new RsMotionHaltedEvent(5.0, RsMotionHaltedEvent.HALTED_ON_COLLISION, 1.1, 1.2, 1.3, 0.799));
            s.sendPlacementEvent(new RsPlacementEvent(6.0, true, "home", 2.5, 2.5, 3.9269908169872414));
            s.sendTargetSelectionEvent(new RsTargetSelectionEvent(7.0, "F3", false));
            s.sendHeartbeatEvent(8.0, 3);
            s.sendEncoderStatusEvent(new RsEncoderStatusEvent(9.0, 2, 5, -17, 40, -1, 12, 4.5, true));
            s.sendPlanEvent(new RsPlanEvent(0.0, null));

            RsMouseClickEvent m = (RsMouseClickEvent) client.events.next();
            assertEquals(1.5, m.simTime);
            assertEquals(1, m.button);
            assertEquals(2, m.clickCount);
            assertEquals(0.25, m.x);
            assertEquals(-3.5, m.y);

            RsPositionEvent p = (RsPositionEvent) client.events.next();
            assertEquals(-3.0, p.orientation);
            assertEquals(0.5, p.velocity);
            assertEquals(-0.25, p.turnRate);

            assertEquals(7, ((RsTimeoutEvent) client.events.next()).timeoutIndex);

            RsMotionStartedEvent started = (RsMotionStartedEvent) client.events.next();
            assertEquals(0.3, started.linearVelocity);
            assertEquals(0.1, started.rotationalVelocity);
            assertEquals(2.5, started.duration);
            assertEquals(0.75, started.orientation);

            RsMotionHaltedEvent halted = (RsMotionHaltedEvent) client.events.next();
            assertEquals("collision", halted.whyHalted());
            assertEquals(0.799, halted.duration);

            RsPlacementEvent placed = (RsPlacementEvent) client.events.next();
            assertTrue(placed.valid);
            assertEquals("home", placed.getName());

            RsTargetSelectionEvent selection = (RsTargetSelectionEvent) client.events.next();
            assertEquals("F3", selection.targetName);
            assertFalse(selection.status);

            RsHeartbeatEvent beat = (RsHeartbeatEvent) client.events.next();
            assertEquals(8.0, beat.simTime);
            assertEquals(3, beat.sequence);

            RsEncoderStatusEvent enc = (RsEncoderStatusEvent) client.events.next();
            assertEquals(2, enc.requestIndex);
            assertEquals(5, enc.encoderID);
            assertEquals(-17, enc.accumulatorValue);
            assertEquals(40, enc.absoluteAccumulatorValue);
            assertEquals(-1, enc.quadratureValue);
            assertEquals(12, enc.encoderInterval);
            assertEquals(4.5, enc.encoderAngle);
            assertTrue(enc.clearOnReport);

            RsPlanEvent plan = (RsPlanEvent) client.events.next();
            assertNull(plan.plan, "a server without a plan sends 'not available'");
            assertEquals(0.0, link.client.getSimTime(), "the plan event resets the client's clock reading");
        }
    }
}
