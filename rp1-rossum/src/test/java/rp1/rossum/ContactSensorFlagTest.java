package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Which contact sensors the collision search flags (behavior.md section 6.3): only the one holding
 * the earliest contact among contact sensors over the whole requested motion, whatever stops the
 * motion. The robot is a 0.15 m round chassis with a front "bumper" (x from 0.12 to 0.16) added
 * before a rear "tail" (x from -0.16 to -0.12), both 0.16 m wide.
 */
class ContactSensorFlagTest {
    private static final double EPS = 1e-9;

    private final RsBodyContactSensor bumper = new RsBodyContactSensor(TestPlans.rect(0.12, -0.08, 0.16, 0.08), 4);
    private final RsBodyContactSensor tail = new RsBodyContactSensor(TestPlans.rect(-0.16, -0.08, -0.12, 0.08), 4);

    private RsBody robot(RsBodyContactSensor... sensors) {
        RsBody body = new RsBody("bumpy");
        body.addPart(new RsBodyCircle(0, 0, 0.15));
        for (RsBodyContactSensor s : sensors) {
            body.addPart(s);
        }
        return body;
    }

    private static RsPlan wallsAcross(String name, double x0, double x1) {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, name, x0, -5, x1, 5);
        return plan;
    }

    @Test
    void aSensorWhoseOwnContactComesLaterIsNotFlagged() {
        RsBody b = robot(bumper, tail);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 3.0), wallsAcross("ahead", 1.0, 1.1));
        assertTrue(bumper.getCollision());
        assertEquals(0.84, bumper.getCollisionTime(), EPS, "the bumper's face at 0.16 reaches x = 1");
        assertEquals("ahead", bumper.getCollisionObjectName());
        assertFalse(tail.getCollision(), "the tail would reach the wall at 1.12 s, after the bumper");
        RsContactSensorEvent[] pressed = b.pressContactSensors(b.motion.time1);
        assertEquals(1, pressed.length);
        assertEquals(bumper.getID(), pressed[0].sensorID);
    }

    /**
     * A robot halted at once starts its next motion from the same pose, where its sensors' outlines
     * are kept from the last search; a sensor added in between is placed and flagged all the same.
     */
    @Test
    void aSensorAddedBetweenTwoMotionsFromTheSamePoseIsFlagged() {
        RsBody b = robot(bumper);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 3.0), wallsAcross("ahead", 1.0, 1.1));
        assertEquals(0.84, bumper.getCollisionTime(), EPS);
        b.addPart(tail);
        b.place(1.0, 0, 0, 0);
        b.computeMotion(1.0, new RsMotionRequest(-1.0, 0.0, 3.0), wallsAcross("behind", -1.1, -1.0));
        assertFalse(bumper.getCollision());
        assertTrue(tail.getCollision());
        assertEquals(0.84, tail.getCollisionTime(), EPS, "the tail's face at -0.16 reaches x = -1");
        assertEquals("behind", tail.getCollisionObjectName());
    }

    @Test
    void aSensorListedEarlierLosesItsFlagWhenALaterOneTouchesFirst() {
        RsBody b = robot(bumper, tail);
        b.place(0.0, 1.0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(-1.0, 0.0, 2.0), wallsAcross("behind", -0.1, 0.0));
        assertFalse(bumper.getCollision(), "its own contact at 1.12 s is beaten by the tail's");
        assertTrue(tail.getCollision());
        assertEquals(0.84, tail.getCollisionTime(), EPS);
        assertEquals("behind", tail.getCollisionObjectName());
    }

    @Test
    void aContactNoEarlierThanTheEarliestSoFarCountsForNothing() {
        RsBodyContactSensor twin = new RsBodyContactSensor(TestPlans.rect(0.12, -0.08, 0.16, 0.08), 4);
        RsBody b = robot(bumper, twin);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 3.0), wallsAcross("ahead", 1.0, 1.1));
        assertTrue(bumper.getCollision());
        assertFalse(twin.getCollision(), "same contact time, not earlier");
    }

    @Test
    void theWallThatLastLoweredTheEarliestContactNamesTheSensor() {
        RsPlan farFirst = new RsPlan();
        TestPlans.box(farFirst, "far", 2.0, -5, 2.1, 5);
        TestPlans.box(farFirst, "near", 1.0, -5, 1.1, 5);
        RsBody b = robot(bumper);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 3.0), farFirst);
        assertEquals("near", bumper.getCollisionObjectName());

        RsPlan nearFirst = new RsPlan();
        TestPlans.box(nearFirst, "near", 1.0, -5, 1.1, 5);
        TestPlans.box(nearFirst, "far", 2.0, -5, 2.1, 5);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 3.0), nearFirst);
        assertEquals("near", bumper.getCollisionObjectName(), "the far wall's later contact changes nothing");
    }

    /**
     * Backing at 1 m/s on heading 70 degrees towards a wall whose face is x = 0.01, from x = 0.5: the
     * chassis sticks out 0.15 m towards it and touches after 0.34 / cos 70 = 0.994 s; the tail's
     * corner sticks out 0.16 cos 70 + 0.08 sin 70 = 0.1299 m and would touch after 1.053 s.
     */
    private RsBody backedObliquely(double seconds) {
        RsBody b = robot(bumper, tail);
        b.place(0.0, 0.5, 2.0, Math.toRadians(70));
        b.computeMotion(0.0, new RsMotionRequest(-1.0, 0.0, seconds), wallsAcross("west", -0.1, 0.01));
        return b;
    }

    @Test
    void theTailGoesHotWhenTheChassisStopsTheMotionShortOfTheTailsContact() {
        RsBody b = backedObliquely(1.2);
        double chassis = 0.34 / Math.cos(Math.toRadians(70));
        assertEquals(Math.floor(1000 * chassis - 0.1) / 1000, b.motion.timeTotal, 1e-12);
        assertTrue(tail.getCollision(), "its contact at 1.053 s lies within the requested 1.2 s");
        RsContactSensorEvent[] pressed = b.pressContactSensors(b.motion.time1);
        assertEquals(1, pressed.length);
        assertEquals(tail.getID(), pressed[0].sensorID);
        assertEquals("west", pressed[0].getNameOfObjectDetected());
    }

    @Test
    void aShortRequestThatTheChassisCutsFlagsNoSensor() {
        RsBody b = backedObliquely(1.02);
        assertTrue(b.motion.collision);
        assertFalse(tail.getCollision(), "the tail's contact at 1.053 s lies beyond the requested 1.02 s");
        assertFalse(bumper.getCollision());
        assertEquals(0, b.pressContactSensors(b.motion.time1).length);
    }

    /** The robot drove from the origin into a wall at x = 1 and its bumper went hot. */
    private RsPlan pressedAgainstWallAhead(RsBody b) {
        RsPlan plan = wallsAcross("ahead", 1.0, 1.1);
        TestPlans.box(plan, "behind", -2.1, -5, -2.0, 5);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 2.0), plan);
        b.pressContactSensors(b.motion.time1);
        assertTrue(bumper.getHot());
        return plan;
    }

    @Test
    void aReleaseNamesTheWallTheNewMotionWillReachThroughThatSensor() {
        RsBody b = robot(bumper);
        RsPlan plan = pressedAgainstWallAhead(b);
        b.computeMotion(1.0, new RsMotionRequest(-1.0, 0.0, 5.0), plan);
        RsContactSensorEvent[] released = b.releaseContactSensors(1.0);
        assertEquals(1, released.length);
        assertEquals("behind", released[0].getNameOfObjectDetected());
    }

    @Test
    void aReleaseNamesNoWallWhenAnotherSensorHoldsTheEarliestContact() {
        RsBody b = robot(bumper, tail);
        RsPlan plan = pressedAgainstWallAhead(b);
        b.computeMotion(1.0, new RsMotionRequest(-1.0, 0.0, 5.0), plan);
        RsContactSensorEvent[] released = b.releaseContactSensors(1.0);
        assertEquals(1, released.length);
        assertEquals("", released[0].getNameOfObjectDetected(), "the tail reaches the wall behind first");
        assertTrue(tail.getCollision());
    }
}
