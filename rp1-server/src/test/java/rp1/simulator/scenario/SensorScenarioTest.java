package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Sensors as a robot drives past things, evaluated every 0.05 s of a 1 m/s motion from x = 1, so the
 * detector is 5 cm further east at each step (behavior.md section 8).
 */
@Timeout(60)
class SensorScenarioTest {

    private static ScenarioClient driveEast(Scenario s, RsBody body, double seconds) {
        ScenarioClient c = s.connect(new ScenarioClient(body));
        c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(1.0, 0.0, seconds)));
        c.sendPlacementRequest("west");
        return c;
    }

    @Test
    void aTargetEntersAndLeavesTheBeamWithTheBinsTheRulesPredict() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL + "target candle { geometry: 5, 3, 0.05; }\n")) {
            ScenarioClient c = driveEast(s, Bodies.withHead("bot"), 4.0);
            c.await(RsMotionHaltedEvent.class);
            List<RsTargetSensorEvent> events = c.events(RsTargetSensorEvent.class);
            assertEquals(3, events.size(), ScenarioClient.describe(new ArrayList<>(events)));
            // Visible while 1 <= 4.84 - x <= sqrt(3): within 45 degrees of the axis and 2 m.
            RsTargetSensorEvent in = events.get(0);
            assertEquals(2.15, in.simTime, 1e-9, "first step with the candle within 2 m");
            assertTrue(in.status);
            assertEquals("candle", in.getNameOfObjectDetected());
            assertEquals(Math.hypot(1.69, 1.0), in.range, 1e-9);
            assertEquals(Math.atan2(1.0, 1.69), in.bearing, 1e-9, "to the left of the sight axis");
            RsTargetSensorEvent nearer = events.get(1);
            assertEquals(2.75, nearer.simTime, 1e-9, "range bin 3 -> 2 when the range drops below 1.5 m");
            assertTrue(nearer.status);
            RsTargetSensorEvent out = events.get(2);
            assertEquals(2.85, out.simTime, 1e-9, "the candle passes 45 degrees off the axis");
            assertFalse(out.status);
            assertEquals(0.0, out.range);
            assertEquals("", out.getNameOfObjectDetected());
        }
    }

    @Test
    void aDeselectedTargetIsNotSensed() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL + "target candle { geometry: 5, 3, 0.05; }\n")) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.withHead("bot")));
            c.sendTargetSelectionRequest("candle", false);
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 4.0)));
            c.sendPlacementRequest("west");
            c.await(RsMotionHaltedEvent.class);
            assertTrue(c.events(RsTargetSensorEvent.class).isEmpty());
        }
    }

    @Test
    void aRangeSensorReportsEachRangeBinAsItApproachesAWall() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_THIN_WALL)) {
            ScenarioClient c = driveEast(s, Bodies.withSonar("bot"), 3.5);
            c.await(RsMotionHaltedEvent.class);
            List<RsRangeSensorEvent> events = c.events(RsRangeSensorEvent.class);
            List<Integer> bins = new ArrayList<>();
            List<Double> times = new ArrayList<>();
            for (RsRangeSensorEvent e : events) {
                assertTrue(e.status);
                assertEquals("thin", e.getNameOfObjectDetected());
                assertEquals(0.0, e.ux, "RP1 0.60 never fills the line of sight of range events");
                bins.add((int) Math.floor(10 * e.range));
                times.add(Math.round(e.simTime * 100) / 100.0);
            }
            assertEquals(Arrays.asList(9, 8, 7, 6, 5, 4, 3), bins, "range = 4.835 - x, one event per 0.1 m bin");
            assertEquals(Arrays.asList(2.85, 2.95, 3.05, 3.15, 3.25, 3.35, 3.45), times);
            assertEquals(0.985, events.get(0).range, 1e-9);
        }
    }

    @Test
    void aPaintSensorCrossingPaintReportsTheRegionThenItsAbsence() throws Exception {
        String paint = "paint stripe { geometry: 3.02, 0.5, 4.02, 0.5, 4.02, 3.5, 3.02, 3.5; region: 3; color: red; }\n";
        try (Scenario s = Scenario.lockstep(Plans.HALL + paint)) {
            ScenarioClient c = driveEast(s, Bodies.withEye("bot"), 4.0);
            c.await(RsMotionHaltedEvent.class);
            List<RsPaintSensorEvent> events = c.events(RsPaintSensorEvent.class);
            assertEquals(2, events.size());
            assertEquals(2.05, events.get(0).simTime, 1e-9);
            assertTrue(events.get(0).status);
            assertEquals(3, events.get(0).region);
            assertEquals(3.05, events.get(1).simTime, 1e-9);
            assertFalse(events.get(1).status);
            assertEquals(0, events.get(1).region);
        }
    }

    @Test
    void aPaintSensorInsensitiveToARegionStillReportsItsCode() throws Exception {
        String paint = "paint stripe { geometry: 3.02, 0.5, 4.02, 0.5, 4.02, 3.5, 3.02, 3.5; region: 3; }\n";
        RsBody body = Bodies.withEye("bot");
        ((rp1.rossum.RsBodyPaintSensor) body.getPartByName("eye")).setRegionSensitivity(1);
        try (Scenario s = Scenario.lockstep(Plans.HALL + paint)) {
            ScenarioClient c = driveEast(s, body, 4.0);
            c.await(RsMotionHaltedEvent.class);
            List<RsPaintSensorEvent> events = c.events(RsPaintSensorEvent.class);
            assertEquals(2, events.size());
            assertFalse(events.get(0).status);
            assertEquals(3, events.get(0).region, "status false, region 3 (section 8.4)");
            assertEquals(0, events.get(1).region);
        }
    }

    @Test
    void aBumperGoesHotAtTheEndOfABlockedMotionAndIsReleasedByTheNextOne() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_THIN_WALL)) {
            ScenarioClient c = driveEast(s, Bodies.withBumper("bot"), 10.0);
            c.once(RsMotionHaltedEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(-0.5, 0.0, 1.0)));
            c.await(RsMotionHaltedEvent.class, h -> h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COMPLETION);
            List<String> order = new ArrayList<>();
            for (RsEvent e : c.events()) {
                if (e instanceof RsContactSensorEvent || e instanceof RsMotionHaltedEvent || e instanceof RsMotionStartedEvent) {
                    order.add(ScenarioClient.describe(e).replaceAll(" @.*| T=.*", ""));
                }
            }
            double hit = Math.floor(1000.0 * (4.995 - 0.16 - 1.0) - 0.1) / 1000.0;
            List<RsContactSensorEvent> contacts = c.events(RsContactSensorEvent.class);
            assertEquals(2, contacts.size(), order.toString());
            assertTrue(contacts.get(0).status);
            assertEquals("thin", contacts.get(0).getNameOfObjectDetected());
            assertEquals(hit, contacts.get(0).simTime, 1e-9, "the bumper reaches 1 cm beyond the chassis and strikes first");
            assertFalse(contacts.get(1).status);
            assertEquals(hit, contacts.get(1).simTime, 1e-9, "released when the next motion starts");
            assertEquals(6, order.size());
            assertTrue(order.get(0).contains("MotionStarted"), order.toString());
            assertTrue(order.get(1).contains("ContactSensor") && order.get(1).contains("true"), "hit before the halt");
            assertTrue(order.get(2).contains("MotionHaltedEvent cause=2"), order.toString());
            assertTrue(order.get(3).contains("MotionStarted"));
            assertTrue(order.get(4).contains("ContactSensor") && order.get(4).contains("false"), "release after the start");
            assertTrue(order.get(5).contains("MotionHaltedEvent cause=0"));
        }
    }

    @Test
    void aSensorPollAnswersWithTheLastComputedStateWhateverTheSubscriptions() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_THIN_WALL)) {
            RsBody body = Bodies.withSonar("bot");
            RsBodyRangeSensor sonar = (RsBodyRangeSensor) body.getPartByName("sonar");
            ScenarioClient c = new ScenarioClient(body);
            // A handler added before the connection exists never subscribes, and then neither do the
            // later ones (docs/protocol.md section 10): the sonar's changes are not sent, polls are.
            c.addRangeSensorEventHandler(sonar, e -> { });
            s.connect(c);
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 3.5)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendSensorStatusRequest(sonar));
            c.sendPlacementRequest("west");
            RsRangeSensorEvent polled = c.await(RsRangeSensorEvent.class);
            assertEquals(3.5, polled.simTime, 1e-9);
            assertEquals(4.835 - 4.5, polled.range, 1e-9);
            assertEquals(1, c.events(RsRangeSensorEvent.class).size(), "no state-change events without a subscription");
        }
    }
}
