package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;

/** Several robots in one world: they meet (beyond RP1 0.60, where they passed through each other). */
@Timeout(60)
class RobotsScenarioTest {

    /** The halts of two round robots that drive towards each other and meet. */
    private record Meeting(RsMotionHaltedEvent a, RsMotionHaltedEvent b) {
        /** Both halted by collision at {@code time}, less than 2.5 mm apart and not overlapping. */
        void bothHaltedAt(double time) {
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, a.causeOfHalt);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, b.causeOfHalt);
            assertEquals(time, a.simTime, 1e-9);
            assertEquals(time, b.simTime, 1e-9);
            double gap = b.x - a.x - 0.3;
            assertTrue(gap > 0 && gap < 0.0025, "less than 2.5 mm apart, not overlapping: " + gap);
        }
    }

    /**
     * Robot a placed at "west" drives east at {@code speedA}; robot b placed at {@code placementB}
     * drives west (it faces west) at 1 m/s, {@code delayB} seconds after it is placed (at once if 0).
     */
    private static Meeting meet(String plan, double speedA, String placementB, double delayB) throws Exception {
        try (Scenario s = Scenario.lockstep(plan)) {
            ScenarioClient a = s.connect(new ScenarioClient(Bodies.round("a")));
            ScenarioClient b = s.connect(new ScenarioClient(Bodies.round("b")));
            a.once(RsPlacementEvent.class, e -> a.sendMotionRequest(new RsMotionRequest(speedA, 0.0, 10.0)));
            RsMotionRequest goB = new RsMotionRequest(1.0, 0.0, 10.0);
            if (delayB > 0) {
                b.once(RsPlacementEvent.class, e -> b.sendTimeoutRequest(delayB));
                b.once(RsTimeoutEvent.class, e -> b.sendMotionRequest(goB));
            } else {
                b.once(RsPlacementEvent.class, e -> b.sendMotionRequest(goB));
            }
            a.sendPlacementRequest("west");
            b.sendPlacementRequest(placementB);
            return new Meeting(a.await(RsMotionHaltedEvent.class), b.await(RsMotionHaltedEvent.class));
        }
    }

    @Test
    void twoRobotsDrivingHeadOnBothHaltByCollisionJustShortOfEachOther() throws Exception {
        Meeting m = meet(Plans.HALL, 1.0, "east", 0);
        // Fronts 7.7 m apart closing at 2 m/s: contact at 3.85 s; both stop at the millisecond before.
        m.bothHaltedAt(3.849);
        assertEquals(1.0 + 3.849, m.a().x, 1e-9);
        assertEquals(9.0 - 3.849, m.b().x, 1e-9);
    }


    @Test
    void robotsOnDifferentEvaluationGridsStillMeet() throws Exception {
        // b sets off 25 ms after a, half a step out of a's grid: fronts 7.7 m apart, contact at 3.8625 s.
        meet(Plans.HALL, 1.0, "east", 0.025).bothHaltedAt(3.862);
    }


    @Test
    void robotsSettingOffHeadOnFromAFewCentimetresApartHaltWithoutOverlapping() throws Exception {
        // Fronts 8 cm apart: they close the gap before either is evaluated again, so the search made
        // when they set off has to find each other. Closing at 2 m/s: contact at 0.04 s; both stop at
        // the millisecond before.
        Meeting m = meet(Plans.HALL + "placement close { geometry: 1.38, 2, 180, 0.1; }\n", 1.0, "close", 0);
        m.bothHaltedAt(0.039);
        assertEquals(1.039, m.a().x, 1e-9);
        assertEquals(1.38 - 0.039, m.b().x, 1e-9);
    }


    @Test
    void aRobotSettingOffTowardsAMovingRobotBetweenItsEvaluationsHaltsBothWithoutOverlapping() throws Exception {
        // a creeps east at 1 cm/s, evaluated at 0, 0.05, ...; b, 1 cm ahead of it, sets off towards it
        // at 0.025 s, half a step into a's grid, and would close the gap before a's next evaluation.
        // Fronts at 1.15 + 0.01 t and 1.16 - (t - 0.025): contact at 0.035 / 1.01 = 0.03465 s.
        Meeting m = meet(Plans.HALL + "placement close { geometry: 1.31, 2, 180, 0.1; }\n", 0.01, "close", 0.025);
        m.bothHaltedAt(0.034);
        assertEquals(1.0 + 0.01 * 0.034, m.a().x, 1e-9);
        assertEquals(1.31 - 0.009, m.b().x, 1e-9);
    }


    @Test
    void aRobotDrivingIntoAParkedRobotStopsAndTheParkedOneHearsNothing() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient parked = s.connect(new ScenarioClient(Bodies.round("parked")));
            parked.sendPlacementRequest("centre");
            parked.await(RsPlacementEvent.class);
            ScenarioClient mover = s.connect(new ScenarioClient(Bodies.round("mover")));
            mover.once(RsPlacementEvent.class, e -> mover.sendMotionRequest(new RsMotionRequest(2.0, 0.0, 5.0)));
            mover.sendPlacementRequest("west");
            RsMotionHaltedEvent h = mover.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, h.causeOfHalt);
            assertEquals(1.0 + 2.0 * Math.floor(1000.0 * 3.7 / 2.0 - 0.1) / 1000.0, h.x, 1e-9, "contact after 3.7 m");
            assertTrue(parked.events(RsMotionHaltedEvent.class).isEmpty());
        }
    }

    @Test
    void rangeSensorsSeeOtherRobots() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient parked = s.connect(new ScenarioClient(Bodies.round("obstacle bot")));
            parked.sendPlacementRequest("centre");
            parked.await(RsPlacementEvent.class);
            ScenarioClient seer = s.connect(new ScenarioClient(Bodies.withSonar("seer")));
            seer.once(RsPlacementEvent.class, e -> seer.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 3.5)));
            seer.sendPlacementRequest("west");
            seer.await(RsMotionHaltedEvent.class);
            RsRangeSensorEvent first = seer.events(RsRangeSensorEvent.class).get(0);
            assertTrue(first.status);
            assertEquals("obstacle bot", first.getNameOfObjectDetected());
            assertEquals(2.7, first.simTime, 1e-9, "the parked robot's back is at x = 4.85: 1 m from the detector once x > 3.69");
        }
    }

    @Test
    void aPlacementOnTopOfAnotherRobotIsRefused() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient first = s.connect(new ScenarioClient(Bodies.round("first")));
            first.sendPlacementRequest("centre");
            assertTrue(first.await(RsPlacementEvent.class).valid);
            ScenarioClient second = s.connect(new ScenarioClient(Bodies.round("second")));
            second.sendPlacementRequest("centre");
            RsPlacementEvent refused = second.await(RsPlacementEvent.class);
            assertFalse(refused.valid);
            assertEquals("centre", refused.name);
        }
    }

    @Test
    void aRobotWhoseClientLeavesIsNoLongerAnObstacle() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient leaving = s.connect(new ScenarioClient(Bodies.round("leaving")));
            leaving.sendPlacementRequest("centre");
            leaving.await(RsPlacementEvent.class);
            s.closeClient(0);
            await(() -> s.simulation().getSessions().isEmpty(), Duration.ofSeconds(10), "the server noticed the client leave");
            ScenarioClient mover = s.connect(new ScenarioClient(Bodies.round("mover")));
            mover.once(RsPlacementEvent.class, e -> mover.sendMotionRequest(new RsMotionRequest(2.0, 0.0, 3.0)));
            mover.sendPlacementRequest("west");
            RsMotionHaltedEvent h = mover.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, h.causeOfHalt, "drove through where it stood");
            assertEquals(7.0, h.x, 1e-9);
        }
    }
}
