package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsEncoder;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.SimulationSettings;
import rp1.simulator.noise.NoiseSettings;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * Seeded noise in whole simulations: off it changes nothing, on it repeats with its seed and changes
 * with another, its errors have the asked size, and the world keeps the truth that the client is not
 * told.
 */
@Timeout(120)
class NoiseScenarioTest {
    /** Every kind of noise at once. */
    private static final NoiseSettings ALL = new NoiseSettings(0.03, 0.1, 0.05, Math.toRadians(3), 0.05, 0.05, 0.1);

    private static SimulationSettings lockstep(long seed, NoiseSettings noise) {
        return SimulationSettings.lockstep(0.05, seed).withNoise(noise);
    }

    /** A round robot with a sonar (1 m, {@code bins} bins) and 200-interval encoders on both wheels. */
    private static RsBody body(String name, int bins, RsEncoder[][] encoders) {
        RsBody body = new RsBody(name);
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        encoders[0] = drive.addEncodersToDefaultWheels(200);
        body.addPart(new RsBodyCircle(0.0, 0.0, Bodies.RADIUS));
        body.addPart(drive);
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(Bodies.box(0.09, 0.16), 4, 0.16, 0.0, 0.0, 1.0, bins);
        sonar.setName("sonar");
        body.addPart(sonar);
        return body;
    }

    /**
     * A wanderer placed at {@code placement}: it halts when its sonar sees a wall within 0.3 m, turns at
     * every halt and reports its encoders, until t = 20 s.
     */
    private static String wander(SimulationSettings settings, String placement) throws InterruptedException {
        try (Scenario s = Scenario.with(Plans.HALL, settings)) {
            RsEncoder[][] encoders = new RsEncoder[1][];
            ScenarioClient c = s.connect(new ScenarioClient(body("wanderer", 10, encoders)));
            int[] turn = {0};
            c.on(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.8, 0.0, 30.0)));
            c.on(RsMotionHaltedEvent.class, e -> {
                c.sendEncoderStatusRequest(encoders[0], false);
                if (e.simTime < 20.0) {
                    turn[0]++;
                    if (e.duration < 0.01) {
                        c.sendMotionRequest(new RsMotionRequest(-0.3, 0.0, 1.0));
                    } else {
                        c.sendMotionRequest(new RsMotionRequest(0.3, (turn[0] % 2 == 0 ? 1 : -1) * 0.9,
                                1.5 + 0.1 * turn[0]));
                    }
                }
            });
            c.on(RsRangeSensorEvent.class, e -> {
                if (e.status && e.range < 0.3) {
                    c.sendHaltRequest();
                }
            });
            c.sendPlacementRequest(placement);
            c.sendTimeoutRequest(25.0);
            c.await(RsTimeoutEvent.class);
            return c.transcript();
        }
    }

    @Test
    void zeroNoiseIsTheNoiselessRun() throws Exception {
        String plain = wander(SimulationSettings.lockstep(0.05, 1L), "$random");
        String zero = wander(lockstep(1L, new NoiseSettings(0, 0, 0, 0, 0, 0, 0)), "$random");
        assertEquals(plain, zero);
    }

    @Test
    void oneSeedGivesOneNoisyRunTwiceAndItIsNotTheNoiselessOne() throws Exception {
        String first = wander(lockstep(2L, ALL), "$random");
        String second = wander(lockstep(2L, ALL), "$random");
        assertTrue(first.split("\n").length > 40, "a long run:\n" + first);
        assertEquals(first, second);
        assertNotEquals(wander(lockstep(2L, NoiseSettings.OFF), "$random"), first);
    }

    @Test
    void anotherSeedGivesOtherNoise() throws Exception {
        assertEquals(wander(lockstep(1L, NoiseSettings.OFF), "west"), wander(lockstep(2L, NoiseSettings.OFF), "west"),
                "without noise a fixed placement makes the seed irrelevant");
        assertNotEquals(wander(lockstep(1L, ALL), "west"), wander(lockstep(2L, ALL), "west"));
    }

    @Test
    void noiseLeavesTheRandomPlacementWhereItWas() throws Exception {
        assertEquals(placedAt(NoiseSettings.OFF), placedAt(ALL));
    }

    private static String placedAt(NoiseSettings noise) throws InterruptedException {
        try (Scenario s = Scenario.with(Plans.HALL, lockstep(9L, noise))) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("$random");
            return ScenarioClient.describe(c.await(RsPlacementEvent.class));
        }
    }

    @Test
    void rangeReadingsScatterAboutTheTruthWithTheAskedSigma() throws Exception {
        double sigma = 0.02;
        List<RsRangeSensorEvent> truth = approach(NoiseSettings.OFF);
        List<RsRangeSensorEvent> noisy = approach(new NoiseSettings(sigma, 0, 0, 0, 0, 0, 0));
        assertEquals(truth.size(), noisy.size(), "the truth decides when a reading changes");
        assertTrue(truth.size() > 50, "readings: " + truth.size());
        double squares = 0;
        for (int i = 0; i < truth.size(); i++) {
            assertEquals(truth.get(i).simTime, noisy.get(i).simTime);
            double error = noisy.get(i).range - truth.get(i).range;
            squares += error * error;
        }
        double rms = Math.sqrt(squares / truth.size());
        assertTrue(rms > 0.6 * sigma && rms < 1.4 * sigma, "rms error " + rms);
    }

    /**
     * The range readings of a robot with a 100-bin sonar driving 5 s at 0.2 m/s from "west" towards a
     * wall at x = 2.5: a reading a step, from 1 m away.
     */
    private static List<RsRangeSensorEvent> approach(NoiseSettings noise) throws InterruptedException {
        try (Scenario s = Scenario.with(Plans.hallWithBlockAt(2.5), lockstep(4L, noise))) {
            ScenarioClient c = s.connect(new ScenarioClient(body("bot", 100, new RsEncoder[1][])));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.2, 0.0, 5.0)));
            c.sendPlacementRequest("west");
            c.await(RsMotionHaltedEvent.class);
            return c.events(RsRangeSensorEvent.class);
        }
    }

    @Test
    void withSlipTheWorldKeepsTheTruthAndTheRobotIsToldTheCommandedMotion() throws Exception {
        try (Scenario s = Scenario.with(Plans.HALL, lockstep(5L, new NoiseSettings(0, 0, 0, 0, 0, 0.2, 0.2)))) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("slipper")));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 2.0)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendPositionRequest());
            c.sendPlacementRequest("centre");
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            RsPositionEvent truth = c.await(RsPositionEvent.class);
            assertEquals(6.0, halted.x, 1e-9, "told: 1 m east of (5, 2), as commanded");
            assertEquals(2.0, halted.y, 1e-9);
            assertTrue(Math.abs(truth.x - 6.0) > 1e-6, "the robot slipped: " + truth.x);
            assertTrue(Math.abs(truth.x - 6.0) < 0.8, "by a fraction of the distance: " + truth.x);
            RobotSnapshot seen = WorldSnapshot.of(s.simulation(), truth.simTime).placedRobots().get(0);
            assertEquals(truth.x, seen.x(), 1e-12, "the window and pictures show the truth");
            assertEquals(truth.y, seen.y(), 1e-12);
            assertEquals(6.0, seen.believed()[0], 1e-9, "and, in grey, where the robot believes it is");
        }
    }

    /**
     * Seed 4 makes a 1 m motion from "west" slip to more than 2.7 m: the walls it meets are gathered
     * for the motion made, not the one commanded, so it stops at a wall the commanded one never reaches
     * (the plan has enough walls, posts along the north wall, for the world to file them in a grid).
     */
    @Test
    void aMotionThatSlipsFurtherThanCommandedStillStopsAtTheWallItMeets() throws Exception {
        StringBuilder plan = new StringBuilder(Plans.hallWithBlockAt(4.0));
        for (int i = 0; i < 30; i++) {
            plan.append("wall post").append(i).append(" { geometry: ").append(0.3 + 0.3 * i).append(", 3.8, ")
                    .append(0.32 + 0.3 * i).append(", 3.8, 0.02; }\n");
        }
        try (Scenario s = Scenario.with(plan.toString(), lockstep(4L, new NoiseSettings(0, 0, 0, 0, 0,
                1.0, 0)))) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("slipper")));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 2.0)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendPositionRequest());
            c.sendPlacementRequest("west");
            RsMotionHaltedEvent halted = c.await(RsMotionHaltedEvent.class);
            RsPositionEvent truth = c.await(RsPositionEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt);
            assertEquals(3.99 - Bodies.RADIUS, truth.x, 0.002, "stopped against the block's face at x = 3.99");
        }
    }

    @Test
    void encodersMissCountsAtTheAskedRate() throws Exception {
        int exact = encoderCount(NoiseSettings.OFF);
        int missing = encoderCount(new NoiseSettings(0, 0, 0, 0, 0.2, 0, 0));
        assertTrue(exact > 500, "counts: " + exact);
        assertEquals(0.8 * exact, missing, 0.05 * exact);
    }

    /** The left encoder's count after 3 m straight ahead from "west". */
    private static int encoderCount(NoiseSettings noise) throws InterruptedException {
        try (Scenario s = Scenario.with(Plans.HALL, lockstep(6L, noise))) {
            RsEncoder[][] encoders = new RsEncoder[1][];
            ScenarioClient c = s.connect(new ScenarioClient(body("bot", 10, encoders)));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 3.0)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendEncoderStatusRequest(encoders[0][0], false));
            c.sendPlacementRequest("west");
            return c.await(RsEncoderStatusEvent.class).accumulatorValue;
        }
    }
}
