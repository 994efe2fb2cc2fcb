package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import rp1.rossum.request.RsMotionRequest;

/** The analytic collision search that cuts motions short (behavior.md sections 6.2 and 6.3). */
class CollisionTest {
    private static final double EPS = 1e-9;

    private static RsBody roundRobot(double radius) {
        RsBody body = new RsBody("round");
        body.addPart(new RsBodyCircle(0, 0, radius));
        return body;
    }

    /** A plan with a wall filling x in [x0, x1] over a tall band. */
    private static RsPlan wallBetween(double x0, double x1) {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "wall", x0, -5, x1, 5);
        return plan;
    }

    /**
     * Walls are tried nearest first, so that the contact found lets the others be passed over: the
     * contact time is still the least over every wall alone, whatever order the walls come in.
     */
    @Test
    void aMotionStopsAtTheEarliestWallWhateverOrderTheWallsComeIn() {
        java.util.Random random = new java.util.Random(3);
        int contacts = 0;
        for (int i = 0; i < 400; i++) {
            RsWall[] walls = new RsWall[2 + random.nextInt(8)];
            for (int w = 0; w < walls.length; w++) {
                double x = (random.nextDouble() - 0.5) * 16;
                double y = (random.nextDouble() - 0.5) * 16;
                walls[w] = new RsWall("w" + w, null);
                walls[w].setGeometry(TestPlans.rect(x, y, x + 0.05 + 3 * random.nextDouble(), y + 0.05 + random.nextDouble()));
            }
            RsMotionRequest request = random.nextBoolean()
                    ? new RsMotionRequest(1.0, 0.0, 20.0) : new RsMotionRequest(0.5, 0.3, 20.0);
            double heading = 2 * Math.PI * random.nextDouble();
            double earliest = Double.POSITIVE_INFINITY;
            for (RsWall w : walls) {
                RsBody alone = roundRobot(0.2);
                alone.place(0.0, 0.0, 0.0, heading);
                alone.computeMotion(0.0, request, new RsWall[] {w});
                if (alone.motion.collision) {
                    earliest = Math.min(earliest, alone.motion.collisionTime);
                }
            }
            for (int shuffle = 0; shuffle < 3; shuffle++) {
                java.util.Collections.shuffle(java.util.Arrays.asList(walls), random);
                RsBody b = roundRobot(0.2);
                b.place(0.0, 0.0, 0.0, heading);
                b.computeMotion(0.0, request, walls);
                assertEquals(Double.isFinite(earliest), b.motion.collision, "case " + i);
                if (b.motion.collision) {
                    assertEquals(earliest, b.motion.collisionTime, 0.0, "case " + i);
                }
            }
            contacts += Double.isFinite(earliest) ? 1 : 0;
        }
        assertTrue(contacts > 100 && contacts < 380, contacts + " of 400 motions meet a wall");
    }

    /**
     * A robot halted as soon as it starts starts its next motion from the same pose, where its
     * outlines are kept from the last search: that search finds what a robot placed there afresh
     * finds, to the bit, and a part added since takes part in it.
     */
    @Test
    void aMotionStartedAgainFromTheSamePoseIsSearchedWithThePartsTheBodyHasNow() {
        RsWall[] walls = wallBetween(1.0, 1.1).getWallArray();
        RsMotionRequest ahead = new RsMotionRequest(1.0, 0.0, 5.0);
        RsMotionRequest arc = new RsMotionRequest(0.5, 0.1, 5.0);
        RsBody b = roundRobot(0.1);
        b.place(0.0, 0.0, 0.3, 0.2);
        b.computeMotion(0.0, ahead, walls);
        assertTrue(b.motion.collision);
        double first = b.motion.collisionTime;
        b.place(1.0, 0.0, 0.3, 0.2);
        b.computeMotion(1.0, arc, walls);
        RsBody fresh = roundRobot(0.1);
        fresh.place(1.0, 0.0, 0.3, 0.2);
        fresh.computeMotion(1.0, arc, walls);
        assertTrue(fresh.motion.collision);
        assertEquals(fresh.motion.collision, b.motion.collision);
        assertEquals(fresh.motion.collisionTime, b.motion.collisionTime, 0.0);
        b.addPart(new RsBodyShape(TestPlans.rect(0.1, -0.02, 0.3, 0.02), 4));
        b.place(2.0, 0.0, 0.3, 0.2);
        b.computeMotion(2.0, ahead, walls);
        assertTrue(b.motion.collisionTime < first - 0.15,
                "a nose reaching 0.2 m beyond the disc meets the wall about 0.2 s sooner: " + b.motion.collisionTime
                + " against " + first);
    }

    @Test
    void backingFrom95CentimetresClearanceStopsOneMillisecondBeforeContact() {
        RsBody b = roundRobot(0.15);
        b.place(0.0, 0.95, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(-1.0, 0.0, 2.0), wallBetween(-0.1, 0.0));
        assertTrue(b.motion.collision);
        assertEquals(0.8, b.motion.collisionTime, EPS);
        assertEquals(0.799, b.motion.timeTotal, 1e-12);
        assertEquals(0.151, b.getPositionEvent(5.0).x, EPS);
        assertTrue(b.getCollision());
    }

    @Test
    void aFastRobotStopsBeforeAOneCentimetreWall() {
        RsBody b = roundRobot(0.15);
        b.place(0.0, 0.0, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(10.0, 0.0, 1.0), wallBetween(1.0, 1.01));
        assertEquals(0.085, b.motion.collisionTime, EPS);
        assertEquals(0.084, b.motion.timeTotal, 1e-12);
        assertEquals(0.84, b.getPositionEvent(1.0).x, EPS);
    }

    @Test
    void aWallCornerStrikingTheMiddleOfAnEdgeIsFound() {
        RsBody b = new RsBody("square");
        b.addPart(new RsBodyShape(TestPlans.rect(-0.5, -0.5, 0.5, 0.5), 4));
        RsPlan plan = new RsPlan();
        RsWall wedge = new RsWall("wedge", plan);
        wedge.setGeometry(new double[] {2.0, 0.0, 3.0, -0.1, 3.0, 0.1});
        plan.addObject(wedge);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 5.0), plan);
        assertEquals(1.5, b.motion.collisionTime, EPS);
        assertEquals(1.499, b.motion.timeTotal, 1e-12);
    }

    @Test
    void aTurningArmStopsBeforeTheWallItSweepsInto() {
        RsBody b = new RsBody("arm");
        b.addPart(new RsBodyShape(TestPlans.rect(0, -0.01, 1, 0.01), 4));
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(0.0, 1.0, 2 * Math.PI), wallBetween(-0.6, -0.5));
        double r = Math.sqrt(1.0001);
        double expected = Math.acos(-0.5 / r) - Math.atan2(0.01, 1.0);
        assertEquals(expected, b.motion.collisionTime, 1e-9);
        assertEquals(Math.floor(1000 * expected - 0.1) / 1000, b.motion.timeTotal, 1e-12);
    }

    @Test
    void aTurningEdgeStrikesAPostThatNoVertexReaches() {
        RsBody b = new RsBody("stick");
        b.addPart(new RsBodyShape(TestPlans.rect(-1, -0.01, 1, 0.01), 4));
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "post", 0.5, 0.5, 0.52, 0.52);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(0.0, 1.0, 2.0), plan);
        double expected = Math.atan2(0.5, 0.52) - Math.asin(0.01 / Math.hypot(0.52, 0.5));
        assertEquals(expected, b.motion.collisionTime, 1e-9);
    }

    @Test
    void turningTheOtherWayHitsAfterTheSameSweep() {
        RsBody b = new RsBody("arm");
        b.addPart(new RsBodyShape(TestPlans.rect(0, -0.01, 1, 0.01), 4));
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(0.0, -2.0, Math.PI), wallBetween(-0.6, -0.5));
        double expected = (Math.acos(-0.5 / Math.sqrt(1.0001)) - Math.atan2(0.01, 1.0)) / 2.0;
        assertEquals(expected, b.motion.collisionTime, 1e-9);
    }

    @Test
    void anArcIntoAWallStopsJustClearOfIt() {
        RsBody b = roundRobot(0.1);
        RsPlan plan = wallBetween(0.9, 1.0);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 1.0, Math.PI), plan);
        assertTrue(b.motion.collision);
        RsTransform end = b.motion.getPoseAtTime(100);
        assertTrue(end.m13 + 0.1 > 0.897 && end.m13 + 0.1 < 0.9004, "stopped at x=" + end.m13);
        assertEquals(false, b.checkForOverlap(plan, end));
        RsTransform beyond = MotionRequests.motionFor(null, 0.0, new RsMotionRequest(1.0, 1.0, Math.PI))
                .getPoseAtTime(b.motion.collisionTime + 0.01);
        assertEquals(true, b.checkForOverlap(plan, beyond));
    }

    @Test
    void onlyOneRevolutionIsExamined() {
        RsBody b = new RsBody("arm");
        b.addPart(new RsBodyShape(TestPlans.rect(0, -0.01, 1, 0.01), 4));
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(0.0, 1.0, 100.0), wallBetween(-0.6, -0.5));
        assertTrue(b.motion.collisionTime < 2.1);
    }

    @Test
    void motionAwayFromAWallIsNotCut() {
        RsBody b = roundRobot(0.15);
        b.place(0.0, 0.5, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 2.0), wallBetween(-0.1, 0.0));
        assertEquals(false, b.motion.collision);
        assertEquals(2.0, b.motion.timeTotal);
    }

    @Test
    void aContactAtOnceLeavesANullMotionWithoutCollision() {
        RsBody b = roundRobot(0.15);
        b.place(0.0, 0.1505, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(-1.0, 0.0, 1.0), wallBetween(-0.1, 0.0));
        assertInstanceOf(RsMotionNull.class, b.motion);
        assertEquals(false, b.motion.collision);
        assertEquals(0.1505, b.getPositionEvent(1.0).x, EPS);
    }

    @Test
    void anEmptyPlanHasNothingToHit() {
        RsBody b = roundRobot(0.15);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 2.0), new RsPlan());
        assertEquals(2.0, b.motion.timeTotal);
    }

    @Test
    void wheelsDoNotCollide() {
        RsBody b = new RsBody("wheels only");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.3, 0.05);
        ds.addDefaultWheels(0.05, 0.02);
        b.addPart(ds);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 2.0), wallBetween(1.0, 1.1));
        assertEquals(false, b.motion.collision);
    }

    /** A round chassis with a contact-sensing bumper at its front. */
    private static RsBody bumperRobot(RsBodyContactSensor... bumpers) {
        RsBody body = roundRobot(0.15);
        for (RsBodyContactSensor s : bumpers) {
            body.addPart(s);
        }
        return body;
    }

    private static RsBodyContactSensor frontBumper() {
        return new RsBodyContactSensor(TestPlans.rect(0.15, -0.05, 0.2, 0.05), 4);
    }

    @Test
    void aFrontBumperReportsContactAfterTheRobotBacksIntoAWall() {
        RsBodyContactSensor bumper = frontBumper();
        RsBody b = bumperRobot(bumper);
        b.place(0.0, 0.95, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(-1.0, 0.0, 2.0), wallBetween(-0.1, 0.0));
        assertEquals(0.799, b.motion.timeTotal, 1e-12);
        assertTrue(bumper.getCollision());
        assertEquals(0, b.releaseContactSensors(0.0).length);
        var pressed = b.pressContactSensors(0.799);
        assertEquals(1, pressed.length);
        assertEquals(true, pressed[0].status);
        assertEquals("wall", pressed[0].getNameOfObjectDetected());
        assertEquals(bumper.getID(), pressed[0].sensorID);
        assertTrue(bumper.getHot());
    }

    /** A bumper robot that drove from the origin into the wall of {@code plan} and stopped there. */
    private static RsBody drivenIntoWall(RsBodyContactSensor bumper, RsPlan plan) {
        RsBody b = bumperRobot(bumper);
        b.place(0.0, 0.0, 0.0, 0.0);
        b.computeMotion(0.0, new RsMotionRequest(1.0, 0.0, 2.0), plan);
        b.pressContactSensors(b.motion.time1);
        return b;
    }

    @Test
    void aPressedBumperIsReleasedWhenTheNextMotionStarts() {
        RsBodyContactSensor bumper = frontBumper();
        RsPlan plan = wallBetween(1.0, 1.1);
        RsBody b = drivenIntoWall(bumper, plan);
        assertTrue(bumper.getHot());
        b.computeMotion(1.0, new RsMotionRequest(-1.0, 0.0, 0.5), plan);
        var released = b.releaseContactSensors(1.0);
        assertEquals(1, released.length);
        assertEquals(false, released[0].status);
        assertEquals("", released[0].getNameOfObjectDetected());
        assertEquals(false, bumper.getHot());
    }

    @Test
    void aBumperPushedOnIntoTheWallStaysPressed() {
        RsBodyContactSensor bumper = frontBumper();
        RsPlan plan = wallBetween(1.0, 1.1);
        RsBody b = drivenIntoWall(bumper, plan);
        b.computeMotion(1.0, new RsMotionRequest(1.0, 0.0, 1.0), plan);
        assertInstanceOf(RsMotionNull.class, b.motion);
        assertEquals(0, b.releaseContactSensors(1.0).length);
        assertEquals(0, b.pressContactSensors(1.0).length);
        assertTrue(bumper.getHot());
    }

    @Test
    void contactSensorsIgnoreStepEvaluations() {
        RsBodyContactSensor bumper = frontBumper();
        bumper.setHot(true);
        assertEquals(false, bumper.computeAndSetState(1.0, wallBetween(0, 1), TestPlans.pose(0, 0, 0)));
        assertEquals(false, bumper.didStateChange());
        assertEquals(true, bumper.getHot());
        assertEquals("", bumper.getSensorEvent(1.0).getNameOfObjectDetected());
    }
}
