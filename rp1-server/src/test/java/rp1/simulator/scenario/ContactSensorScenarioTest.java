package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Which contact sensors go hot (behavior.md section 6.3), as a client sees it: among contact sensors
 * only the one whose contact comes earliest in the whole requested motion is reported, whatever
 * stops the motion. The robot is the 0.15 m round chassis with a front "bumper" (x from 0.12 to
 * 0.16) added before a rear "tail" (x from -0.16 to -0.12); both sensors are subscribed. Motions
 * start at time 0 from the placement; a motion cut by a collision stops at the last whole
 * millisecond at least 0.1 ms before the contact.
 */
@Timeout(60)
class ContactSensorScenarioTest {
    private static final double EPS = 1e-9;

    /** The stop time of a motion whose first contact is {@code contact} seconds after its start. */
    private static double stopBefore(double contact) {
        return Math.floor(1000.0 * contact - 0.1) / 1000.0;
    }

    /** A run: the robot placed at {@code placement}, then the given motions one after another. */
    private static final class Run {
        final RsBody body = Bodies.withBumperAndTail("bot");
        final ScenarioClient client;

        Run(Scenario s, String placement, RsMotionRequest... motions) throws InterruptedException {
            client = s.connect(new ScenarioClient(body));
            client.once(RsPlacementEvent.class, e -> client.sendMotionRequest(motions[0]));
            for (int i = 1; i < motions.length; i++) {
                RsMotionRequest next = motions[i];
                int after = i;
                client.on(RsMotionHaltedEvent.class, h -> {
                    if (client.events(RsMotionHaltedEvent.class).size() == after) {
                        client.sendMotionRequest(next);
                    }
                });
            }
            client.sendPlacementRequest(placement);
            client.await(RsMotionHaltedEvent.class, h -> client.events(RsMotionHaltedEvent.class).size() == motions.length);
        }

        int id(String part) {
            return body.getPartByName(part).getID();
        }

        List<RsContactSensorEvent> contacts() {
            return client.events(RsContactSensorEvent.class);
        }

        RsMotionHaltedEvent halt(int index) {
            return client.events(RsMotionHaltedEvent.class).get(index);
        }

        void assertContact(int index, String sensor, boolean hot, double time, String wall) {
            RsContactSensorEvent e = contacts().get(index);
            String what = "contact event " + index + ": " + ScenarioClient.describe(e);
            assertEquals(id(sensor), e.sensorID, what);
            assertEquals(hot, e.status, what);
            assertEquals(time, e.simTime, EPS, what);
            assertEquals(wall, e.getNameOfObjectDetected(), what);
        }

        void assertTailSilent() {
            for (RsContactSensorEvent e : contacts()) {
                assertTrue(e.sensorID != id("tail"), "the tail must send nothing: " + ScenarioClient.describe(e));
            }
        }

        /**
         * The bumper went hot against {@code wall} when the first motion halted by collision at
         * {@code hit}, the next motion released it at once, and the tail sent nothing.
         */
        void assertOnlyTheBumperPressedThenReleased(double hit, String wall) {
            assertEquals(2, contacts().size(), client.transcript());
            assertContact(0, "bumper", true, hit, wall);
            assertContact(1, "bumper", false, hit, "");
            assertTailSilent();
            assertHalt(0, RsMotionHaltedEvent.HALTED_ON_COLLISION, hit);
        }

        void assertHalt(int index, int cause, double time) {
            RsMotionHaltedEvent h = halt(index);
            assertEquals(cause, h.causeOfHalt, ScenarioClient.describe(h));
            assertEquals(time, h.simTime, EPS, ScenarioClient.describe(h));
        }
    }

    /** Backs away for a moment so that a pressed bumper is released. */
    private static final RsMotionRequest BACK_OFF = new RsMotionRequest(-0.5, 0.0, 0.2);

    @Test
    void drivingIntoAWallAheadPressesOnlyTheBumperWhichTheNextMotionReleases() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_THIN_WALL)) {
            // From x = 1 the bumper's face (x + 0.16) reaches the wall's face 4.995 after 3.835 s; the
            // tail would reach it after 4.115 s, well within the 10 s requested.
            Run r = new Run(s, "west", new RsMotionRequest(1.0, 0.0, 10.0), BACK_OFF);
            double hit = stopBefore(3.835);
            assertEquals(3.834, hit, EPS);
            r.assertOnlyTheBumperPressedThenReleased(hit, "thin");
            r.assertHalt(1, RsMotionHaltedEvent.HALTED_ON_COMPLETION, hit + 0.2);
        }
    }

    @Test
    void anArcIntoAWallPressesOnlyTheBumper() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.hallWithBlockAt(2.0))) {
            // v = 1, w = 0.5: the robot turns left about (1, 4), body point (0, 2). The bumper's outer
            // corner (0.16, -0.08) lies at (0.16, -2.08) from the pivot and meets the wall's face
            // x = 1.99 (0.99 east of the pivot) after turning by atan2(2.08, 0.16) - acos(0.99 / r).
            // The tail would meet it after about 0.553 rad, within the 1.5 rad requested.
            Run r = new Run(s, "west", new RsMotionRequest(1.0, 0.5, 3.0), BACK_OFF);
            double turn = Math.atan2(2.08, 0.16) - Math.acos(0.99 / Math.hypot(0.16, 2.08));
            double hit = stopBefore(turn / 0.5);
            assertEquals(0.835, hit, EPS);
            r.assertOnlyTheBumperPressedThenReleased(hit, "block");
        }
    }

    @Test
    void aPivotNextToAWallPressesOnlyTheBumperWhoseCornerSwingsIn() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.hallWithBlockAt(1.18))) {
            // The wall's face is 0.17 m ahead of the centre: clear of the bumper's face (0.16) but not
            // of its corners (0.1789 from the centre). Turning left at 1 rad/s, the corner
            // (0.16, -0.08) touches after atan2(0.08, 0.16) - acos(0.17 / r) rad; the tail's corner
            // would swing in after about 2.36 s of the 4 s requested.
            Run r = new Run(s, "west", new RsMotionRequest(0.0, 1.0, 4.0), BACK_OFF);
            double turn = Math.atan2(0.08, 0.16) - Math.acos(0.17 / Math.hypot(0.16, 0.08));
            double hit = stopBefore(turn);
            assertEquals(0.147, hit, EPS);
            r.assertOnlyTheBumperPressedThenReleased(hit, "block");
        }
    }

    /** Backing at 1 m/s from x = 1: the tail's face (x - 0.16) reaches the west wall's face 0.01 after 0.83 s. */
    private static void assertOnlyTheTailGoesHotBackingInto(RsMotionRequest request) throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            Run r = new Run(s, "west", request);
            double hit = stopBefore(0.83);
            assertEquals(0.829, hit, EPS);
            assertEquals(1, r.contacts().size(), r.client.transcript());
            r.assertContact(0, "tail", true, hit, "westWall");
            r.assertHalt(0, RsMotionHaltedEvent.HALTED_ON_COLLISION, hit);
        }
    }

    @Test
    void backingStraightIntoAWallPressesOnlyTheTail() throws Exception {
        assertOnlyTheTailGoesHotBackingInto(new RsMotionRequest(-1.0, 0.0, 0.9));
    }

    @Test
    void backingFarEnoughToCarryTheBumperIntoTheSameWallStillPressesOnlyTheTail() throws Exception {
        // The bumper's rear edge (x + 0.12) would reach the wall after 1.11 s of the 2 s requested.
        assertOnlyTheTailGoesHotBackingInto(new RsMotionRequest(-1.0, 0.0, 2.0));
    }

    /**
     * Backing at 1 m/s from (0.5, 2) on heading 70 degrees towards the west wall's face x = 0.01: the
     * chassis reaches 0.15 m towards it and touches after 0.34 / cos 70 = 0.994 s; the tail's corner
     * (-0.16, 0.08) reaches only 0.16 cos 70 + 0.08 sin 70 = 0.1299 m and would touch after 1.053 s.
     */
    private static Run backObliquely(Scenario s, double seconds) throws InterruptedException {
        return new Run(s, "slant", new RsMotionRequest(-1.0, 0.0, seconds));
    }

    private static final double OBLIQUE_CHASSIS_CONTACT = 0.34 / Math.cos(Math.toRadians(70));

    @Test
    void backingObliquelyWithALongRequestPressesTheTailThoughTheChassisStopsItShort() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_SLANT)) {
            Run r = backObliquely(s, 1.2);
            double hit = stopBefore(OBLIQUE_CHASSIS_CONTACT);
            assertEquals(0.993, hit, EPS);
            r.assertHalt(0, RsMotionHaltedEvent.HALTED_ON_COLLISION, hit);
            double tailGap = r.halt(0).x - 0.1299 - 0.01;
            assertTrue(tailGap > 0.019 && tailGap < 0.021, "the tail stops about 2 cm short of the wall: " + tailGap);
            assertEquals(1, r.contacts().size(), r.client.transcript());
            r.assertContact(0, "tail", true, hit, "westWall");
        }
    }

    @Test
    void backingObliquelyWithAShortRequestPressesNothing() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL_WITH_SLANT)) {
            Run r = backObliquely(s, 1.02);
            r.assertHalt(0, RsMotionHaltedEvent.HALTED_ON_COLLISION, stopBefore(OBLIQUE_CHASSIS_CONTACT));
            assertEquals(new ArrayList<>(), r.contacts(), r.client.transcript());
        }
    }
}
