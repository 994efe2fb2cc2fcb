package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import rp1.rossum.RsAckermanSteering;
import rp1.rossum.RsBody;
import rp1.rossum.RsBodyShape;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.SimulationSettings;

/** Motions from request to halt, with numbers worked out by hand (behavior.md sections 5 and 6). */
@Timeout(60)
class MotionScenarioTest {

    /** Places a round robot at {@code placement} and sends {@code request} when it is placed. */
    private static ScenarioClient drive(Scenario s, String placement, RsMotionRequest request) {
        ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
        c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(request));
        c.sendPlacementRequest(placement);
        return c;
    }

    @Test
    void aStraightMotionEndsWhereAndWhenTheRequestSays() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(0.5, 0.0, 2.0));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            RsMotionStartedEvent started = c.events(RsMotionStartedEvent.class).get(0);
            assertEquals(0.0, started.simTime);
            assertEquals(2.0, started.duration);
            assertEquals(1.0, started.x);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt);
            assertEquals(2.0, halted.simTime, 1e-12);
            assertEquals(2.0, halted.duration, 1e-12);
            assertEquals(2.0, halted.x, 1e-12, "1 m east of the start: 0.5 m/s for 2 s");
            assertEquals(2.0, halted.y, 1e-12);
            assertEquals(0.0, halted.orientation, 1e-12);
        }
    }

    @Test
    void aMotionWithANaNTurnRateIsRefusedByTheLibraryAndTheRobotStaysWhereItIs() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west");
            c.await(RsPlacementEvent.class);
            IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                    () -> c.sendMotionRequest(new RsMotionRequest(0.5, Double.NaN, 2.0)));
            assertEquals("rotationalVelocity must be a finite number, got NaN", refused.getMessage());
            c.once(RsTimeoutEvent.class, e -> c.sendPositionRequest());
            c.sendTimeoutRequest(1.0);
            RsPositionEvent p = c.await(RsPositionEvent.class);
            assertEquals(1.0, p.simTime, 1e-12);
            assertEquals(1.0, p.x, 0.0, "the robot is where it was placed, not at NaN");
            assertEquals(2.0, p.y, 0.0);
            assertEquals(0.0, p.orientation, 0.0);
        }
    }

    @Test
    void aTurnRateJustUnderATenthOfADegreePerSecondDrivesStraightIntoAWallInALargePlan() throws Exception {
        // 25 small walls out of the way make the plan large enough for walls to be looked up near the
        // motion; at 1 cm/s the arc the server must NOT assume (radius 5.7 m) would not reach x = 8.
        StringBuilder plan = new StringBuilder(Plans.hallWithBlockAt(8.0));
        for (int i = 0; i < 25; i++) {
            double x = 5.0 + 0.1 * i;
            plan.append("wall bit").append(i).append(" { geometry: ").append(x).append(", 3.8, ").append(x + 0.05)
                    .append(", 3.8, 0.01; }\n");
        }
        try (Scenario s = Scenario.lockstep(plan.toString())) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(0.01, 0.0017453, 1000.0));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt);
            assertEquals(8.0 - 0.01 - 0.15, halted.x, 0.002, "stopped by the block, driving straight");
            assertEquals(2.0, halted.y, 1e-9);
        }
    }

    @ParameterizedTest(name = "{0} m/s, evaluated every {1} s")
    @CsvSource({"1, 0.05", "5, 0.05", "10, 0.05", "10, 1.0", "10, 0.001"})
    void aOneCentimetreWallStopsTheRobotAtAnySpeedAndModellingRate(double speed, double interval) throws Exception {
        try (Scenario s = Scenario.with(Plans.HALL_WITH_THIN_WALL, SimulationSettings.lockstep(interval, 1L))) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(speed, 0.0, 10.0));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            double contact = (4.995 - 0.15 - 1.0) / speed;
            double stop = Math.floor(1000.0 * contact - 0.1) / 1000.0;
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt);
            assertEquals(stop, halted.simTime, 1e-9, "stopped at the last whole millisecond before contact");
            assertEquals(1.0 + speed * stop, halted.x, 1e-9);
            double gap = 4.995 - (halted.x + 0.15);
            assertTrue(gap > 0 && gap <= 0.0011 * speed + 1e-9, "short of the wall face by at most 1.1 ms of travel: " + gap);
            RsMotionStartedEvent started = c.events(RsMotionStartedEvent.class).get(0);
            assertEquals(stop, started.duration, 1e-9, "motion started already reports the shortened duration");
        }
    }

    @Test
    void anArcEndsWhereTheKinematicsSay() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "centre", new RsMotionRequest(0.25, 0.5, 2 * Math.PI));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(2 * Math.PI, halted.simTime, 1e-12);
            assertEquals(5.0, halted.x, 1e-9, "half a turn on a 0.5 m radius about (5, 2.5)");
            assertEquals(3.0, halted.y, 1e-9);
            assertEquals(Math.PI, Math.abs(halted.orientation), 1e-9);
        }
    }

    @Test
    void aReverseArcTurnsAgainstItsRotationalVelocity() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "centre", new RsMotionRequest(-0.5, 0.5, 1.0));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(-0.5, halted.orientation, 1e-12, "backing with w = +0.5 turns the heading by -0.5 rad");
            assertEquals(5.0 + Math.sin(-0.5), halted.x, 1e-9, "rotated about the pivot (5, 3), to the left");
            assertEquals(3.0 - Math.cos(-0.5), halted.y, 1e-9);
        }
    }

    @Test
    void aNullRequestHaltsAtOnceWithCompletionAndNoStart() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(0.0, 0.0, 5.0));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt);
            assertEquals(0.0, halted.duration);
            assertTrue(c.events(RsMotionStartedEvent.class).isEmpty());
        }
    }

    @Test
    void aHaltRequestStopsTheMotionAtTheAnalyticPoseOfThatInstant() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(1.0, 0.0, 5.0));
            c.once(RsMotionStartedEvent.class, e -> c.sendTimeoutRequest(1.234));
            c.once(rp1.rossum.event.RsTimeoutEvent.class, e -> c.sendHaltRequest());
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_REQUEST, halted.causeOfHalt);
            assertEquals(1.234, halted.simTime, 1e-12);
            assertEquals(1.234, halted.duration, 1e-12);
            assertEquals(2.234, halted.x, 1e-9, "between two modelling steps");
        }
    }

    @Test
    void aNewRequestReplacesAMotionUnderWayWithoutAHaltedEvent() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(1.0, 0.0, 5.0));
            c.once(RsMotionStartedEvent.class, e -> c.sendTimeoutRequest(1.0));
            c.once(rp1.rossum.event.RsTimeoutEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 1.0)));
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            List<RsMotionStartedEvent> starts = c.events(RsMotionStartedEvent.class);
            assertEquals(2, starts.size());
            assertEquals(1, c.events(RsMotionHaltedEvent.class).size());
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt);
            assertEquals(2.0, starts.get(1).x, 1e-9, "the second motion starts where the first had got to");
            assertEquals(2.5, halted.x, 1e-9);
        }
    }

    @Test
    void positionReportsTheExactPoseAndTheLastMotionsRates() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = drive(s, "west", new RsMotionRequest(-0.4, 0.0, 1.0));
            c.once(RsMotionHaltedEvent.class, e -> c.sendPositionRequest());
            RsPositionEvent p = c.await(RsPositionEvent.class);
            assertEquals(0.6, p.x, 1e-12);
            assertEquals(-0.4, p.velocity, 1e-12, "backing: negative velocity, even after the motion ended");
            assertEquals(0.0, p.turnRate);
        }
    }

    @Test
    void anAckermanCarRefusesToPivotButTheServerExecutesAnyMotion() throws Exception {
        RsBody car = new RsBody("car");
        RsAckermanSteering steering = new RsAckermanSteering(0.3, 0.4, 0.06, Math.toRadians(35), false);
        steering.addDefaultWheels(0.06, 0.03, 0.04, 0.01);
        car.addPart(new RsBodyShape(new double[] {-0.1, -0.18, 0.5, -0.18, 0.5, 0.18, -0.1, 0.18}, 4));
        car.addPart(steering);
        assertEquals(null, steering.getMotionRequestForPivot(0.0, 1.0, 0.5), "the helper refuses a pivot");
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(car));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.0, Math.PI / 2, 1.0)));
            c.sendPlacementRequest("centre");
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            assertEquals(Math.PI / 2, halted.orientation, 1e-9, "a plain motion request pivots it anyway (section 5.3)");
        }
    }
}
