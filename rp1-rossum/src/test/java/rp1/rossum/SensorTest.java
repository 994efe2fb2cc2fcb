package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;

/** Target, range and paint sensors on small hand-built plans (behavior.md section 8). */
class SensorTest {
    private static final double EPS = 1e-9;
    private static final double[] HEAD = TestPlans.rect(-0.02, -0.02, 0.02, 0.02);

    /** Detector at the body origin, 90 degree field of view, 4 m, 3 width bins, 4 range bins. */
    private static RsBodyTargetSensor eye() {
        return new RsBodyTargetSensor(HEAD, 4, 0, 0, 0, Math.PI / 2, 4.0, 3, 4);
    }

    private static RsTargetSensorEvent event(RsBodyTargetSensor s) {
        return (RsTargetSensorEvent) s.getSensorEvent(1.0);
    }

    @Test
    void aTargetAheadIsDetectedWithItsRangeAndBins() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "candle", 2.0, 0.0);
        RsBodyTargetSensor s = eye();
        assertEquals(true, s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0)));
        RsTargetSensorEvent e = event(s);
        assertEquals(true, e.status);
        assertEquals(2.0, e.range, EPS);
        assertEquals(0.0, e.bearing, EPS);
        assertEquals(2.0, e.xDetection, EPS);
        assertEquals("candle", e.getNameOfObjectDetected());
        assertEquals(s.getID(), e.sensorID);
        assertEquals(2, s.getRangeBin());
        assertEquals(1, s.getWidthBin());
    }

    @Test
    void approachingChangesTheRangeBinAndMovingWithinABinDoesNot() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "candle", 2.0, 0.0);
        RsBodyTargetSensor s = eye();
        s.computeAndSetState(1.0, plan, TestPlans.pose(-0.3, 0, 0));
        assertEquals(2, s.getRangeBin());
        assertEquals(false, s.computeAndSetState(2.0, plan, TestPlans.pose(-0.2, 0, 0)));
        assertEquals(true, s.computeAndSetState(3.0, plan, TestPlans.pose(0.5, 0, 0)));
        assertEquals(1, s.getRangeBin());
    }

    @Test
    void turningMovesTheTargetAcrossWidthBinsThenOutOfView() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "candle", 2.0, 0.0);
        RsBodyTargetSensor s = eye();
        s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0));
        assertEquals(true, s.computeAndSetState(2.0, plan, TestPlans.pose(0, 0, Math.toRadians(30))));
        assertEquals(0, s.getWidthBin());
        RsTargetSensorEvent e = event(s);
        assertEquals(Math.toRadians(-30), e.bearing, EPS);
        assertEquals(2 * Math.cos(Math.toRadians(30)), e.xDetection, EPS);
        assertEquals(-1.0, e.yDetection, EPS);
        assertEquals(true, s.computeAndSetState(3.0, plan, TestPlans.pose(0, 0, Math.toRadians(60))));
        assertEquals(false, event(s).status);
        assertEquals(false, s.computeAndSetState(4.0, plan, TestPlans.pose(0, 0, Math.toRadians(70))));
    }

    @Test
    void aLostTargetReportsZerosButStillTheDetectorAndAxis() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "candle", 2.0, 0.0);
        RsBodyTargetSensor s = eye();
        s.computeAndSetState(1.0, plan, TestPlans.pose(1, 1, Math.PI));
        RsTargetSensorEvent e = event(s);
        assertEquals(false, e.status);
        assertEquals(1.0, e.x, EPS);
        assertEquals(1.0, e.y, EPS);
        assertEquals(-1.0, e.ux, EPS);
        assertEquals(0.0, e.uy, EPS);
        assertEquals(0.0, e.range);
        assertEquals(0.0, e.bearing);
        assertEquals("", e.getNameOfObjectDetected());
    }

    @Test
    void theSightAngleIsAppliedTwice() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "candle", Math.cos(1.0), Math.sin(1.0));
        RsBodyTargetSensor s = new RsBodyTargetSensor(HEAD, 4, 0, 0, 0.5, 0.1, 4.0, 1, 1);
        s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0));
        RsTargetSensorEvent e = event(s);
        assertEquals(true, e.status);
        assertEquals(Math.cos(1.0), e.ux, EPS);
        assertEquals(Math.sin(1.0), e.uy, EPS);
    }

    @Test
    void theNearestVisibleSelectedTargetWins() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "far", 3.0, 0.0);
        RsTarget near = TestPlans.target(plan, "near", 1.0, 0.2);
        RsBodyTargetSensor s = eye();
        s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0));
        assertEquals("near", event(s).getNameOfObjectDetected());
        near.setSelected(false);
        assertEquals(true, s.computeAndSetState(2.0, plan, TestPlans.pose(0, 0, 0)));
        assertEquals("far", event(s).getNameOfObjectDetected());
    }

    @Test
    void aWallHidesATargetButNotOneInFrontOfIt() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "screen", 1.5, -1, 1.6, 1);
        TestPlans.target(plan, "behind", 2.0, 0.0);
        RsBodyTargetSensor s = eye();
        assertEquals(false, s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0)));
        TestPlans.target(plan, "before", 3.0, 0.0);
        TestPlans.target(plan, "front", 1.0, 0.0);
        s.computeAndSetState(2.0, plan, TestPlans.pose(0, 0, 0));
        assertEquals("front", event(s).getNameOfObjectDetected());
    }

    @Test
    void targetsBeyondMaxRangeAreNotSeenAndOmniSensorsSeeBehind() {
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "behind", -3.0, 0.0);
        RsBodyTargetSensor omni = new RsBodyTargetSensor(HEAD, 4, 0, 0, 0, 0, 4.0, 5, 4);
        omni.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0));
        assertEquals(true, event(omni).status);
        assertEquals(0, omni.getWidthBin());
        assertEquals(true, omni.computeAndSetState(2.0, plan, TestPlans.pose(1.1, 0, 0)));
        assertEquals(false, event(omni).status);
    }

    @Test
    void aDifferentTargetInTheSameBinsIsAChange() {
        RsPlan plan = new RsPlan();
        RsTarget a = TestPlans.target(plan, "a", 2.0, 0.0);
        TestPlans.target(plan, "b", 2.0, 0.01);
        RsBodyTargetSensor s = eye();
        s.computeAndSetState(1.0, plan, TestPlans.pose(0, 0, 0));
        assertEquals("a", event(s).getNameOfObjectDetected());
        a.setSelected(false);
        assertEquals(true, s.computeAndSetState(2.0, plan, TestPlans.pose(0, 0, 0)));
    }

    /** Range sensor at the body origin looking ahead, 1 m, 4 bins. */
    private static RsBodyRangeSensor ranger() {
        return new RsBodyRangeSensor(HEAD, 4, 0, 0, 0, 1.0, 4);
    }

    private static RsRangeSensorEvent event(RsBodyRangeSensor s) {
        return (RsRangeSensorEvent) s.getSensorEvent(1.0);
    }

    @Test
    void rangeBinsChangeWhileApproachingAWall() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "wall", 2.0, -1, 2.1, 1);
        RsBodyRangeSensor s = ranger();
        assertEquals(false, s.computeAndSetState(1.0, plan, TestPlans.pose(0.5, 0, 0)));
        assertEquals(true, s.computeAndSetState(2.0, plan, TestPlans.pose(1.1, 0, 0)));
        assertEquals(3, s.getRangeBin());
        assertEquals(0.9, event(s).range, EPS);
        assertEquals(true, s.computeAndSetState(3.0, plan, TestPlans.pose(1.3, 0, 0)));
        assertEquals(2, s.getRangeBin());
        assertEquals(false, s.computeAndSetState(4.0, plan, TestPlans.pose(1.35, 0, 0)));
        assertEquals(true, s.computeAndSetState(5.0, plan, TestPlans.pose(0.5, 0, 0)));
        assertEquals(false, event(s).status);
    }

    @Test
    void aWallAtExactlyMaxRangeIsNotDetected() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "wall", 2.0, -1, 2.1, 1);
        RsBodyRangeSensor s = ranger();
        assertEquals(false, s.computeAndSetState(1.0, plan, TestPlans.pose(1.0, 0, 0)));
        assertEquals(false, event(s).status);
    }

    @Test
    void rangeEventsCarryTheWallNameAndZeroSightVector() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "north wall", -1, 2.0, 1, 2.1);
        RsBodyRangeSensor s = new RsBodyRangeSensor(HEAD, 4, 0.1, 0, Math.PI / 2, 1.0, 4);
        s.computeAndSetState(1.0, plan, TestPlans.pose(0, 1.5, 0));
        RsRangeSensorEvent e = event(s);
        assertEquals(true, e.status);
        assertEquals(0.5, e.range, EPS);
        assertEquals(0.1, e.x, EPS);
        assertEquals(0.0, e.ux);
        assertEquals(0.0, e.uy);
        assertEquals("north wall", e.getNameOfObjectDetected());
    }

    /** Region 1 on [0, 2] x [-1, 1], region 2 on top of it on [1, 1.5] x [-1, 1]. */
    private static RsPlan track() {
        RsPlan plan = new RsPlan();
        TestPlans.paint(plan, "outside", 1, 0, -1, 2, 1);
        TestPlans.paint(plan, "inside", 2, 1, -1, 1.5, 1);
        return plan;
    }

    private static RsPaintSensorEvent event(RsBodyPaintSensor s) {
        return (RsPaintSensorEvent) s.getSensorEvent(1.0);
    }

    @Test
    void paintSensorReportsTheTopmostRegionAndIsColdOverAnInsensitiveOne() {
        RsPlan plan = track();
        RsBodyPaintSensor s = new RsBodyPaintSensor(HEAD, 4, 0.1, 0);
        s.setRegionSensitivity(1);
        assertEquals(true, s.computeAndSetState(1.0, plan, TestPlans.pose(0.5, 0, 0)));
        assertEquals(true, event(s).status);
        assertEquals(1, event(s).region);
        assertEquals(true, s.computeAndSetState(2.0, plan, TestPlans.pose(1.1, 0, 0)));
        assertEquals(false, event(s).status);
        assertEquals(2, event(s).region);
        assertEquals(false, s.computeAndSetState(3.0, plan, TestPlans.pose(1.2, 0, 0)));
        assertEquals(true, s.computeAndSetState(4.0, plan, TestPlans.pose(3.0, 0, 0)));
        assertEquals(0, event(s).region);
        assertEquals(3.1, event(s).x, EPS);
    }

    @Test
    void aPaintSensorWithoutAListSensesEveryRegion() {
        RsBodyPaintSensor s = new RsBodyPaintSensor(HEAD, 4, 0, 0);
        s.computeAndSetState(1.0, track(), TestPlans.pose(1.2, 0, 0));
        assertEquals(true, event(s).status);
        assertEquals(2, event(s).region);
    }

    @Test
    void thePaintBoundaryCountsAsOutside() {
        RsBodyPaintSensor s = new RsBodyPaintSensor(HEAD, 4, 0, 0);
        s.computeAndSetState(1.0, track(), TestPlans.pose(2.0, 0, 0));
        assertEquals(false, event(s).status);
        assertEquals(0, event(s).region);
    }

    @Test
    void theBodyEvaluatesAllItsSensorsAndSaysWhetherAnyChanged() {
        RsBody b = new RsBody("sensing");
        RsBodyPaintSensor paint = new RsBodyPaintSensor(HEAD, 4, 0, 0);
        RsBodyRangeSensor range = ranger();
        b.addPart(range);
        b.addPart(paint);
        RsPlan plan = track();
        assertEquals(true, b.processSensors(1.0, plan, TestPlans.pose(0.5, 0, 0)));
        assertEquals(true, paint.didStateChange());
        assertEquals(false, range.didStateChange());
        assertEquals(1.0, paint.getTimeOfLastStateComputation());
        assertEquals(false, b.processSensors(2.0, plan, TestPlans.pose(0.6, 0, 0)));
    }

    /**
     * A sensor keeps the direction it looked in while the robot's heading stays the same to the bit
     * (a robot driving straight): every reading along such a drive, and after each turn, is the one a
     * sensor that never looked before gives, to the bit.
     */
    @Test
    void readingsAlongStraightDrivesAndTurnsAreThoseOfAFreshSensor() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "east", 2.0, -3, 2.1, 3);
        TestPlans.box(plan, "north", -3, 2.0, 3, 2.1);
        TestPlans.target(plan, "beacon", 1.5, 1.5);
        java.util.Random random = new java.util.Random(7);
        RsBodyRangeSensor range = new RsBodyRangeSensor(HEAD, 4, 0.1, 0, 0.3, 2.5, 8);
        RsBodyTargetSensor eye = new RsBodyTargetSensor(HEAD, 4, 0.1, 0, 0.2, Math.PI / 2, 4.0, 5, 8);
        int seen = 0;
        for (int turn = 0; turn < 50; turn++) {
            RsTransform pose = TestPlans.pose(0, 0, 2 * Math.PI * random.nextDouble());
            for (int step = 0; step < 20; step++) {
                pose.m13 = -1 + 2 * random.nextDouble();
                pose.m23 = -1 + 2 * random.nextDouble();
                double time = turn * 20 + step;
                RsBodyRangeSensor freshRange = new RsBodyRangeSensor(HEAD, 4, 0.1, 0, 0.3, 2.5, 8);
                RsBodyTargetSensor freshEye = new RsBodyTargetSensor(HEAD, 4, 0.1, 0, 0.2, Math.PI / 2, 4.0, 5, 8);
                range.computeAndSetState(time, plan, pose);
                freshRange.computeAndSetState(time, plan, pose);
                eye.computeAndSetState(time, plan, pose);
                freshEye.computeAndSetState(time, plan, pose);
                assertEquals(text(freshRange.getSensorEvent(time)), text(range.getSensorEvent(time)));
                assertEquals(text(freshEye.getSensorEvent(time)), text(eye.getSensorEvent(time)));
                seen += range.getHot() ? 1 : 0;
            }
        }
        assertEquals(true, seen > 100 && seen < 900, seen + " of 1000 readings see a wall");
    }

    /** Every number of a range or target reading, as its bits. */
    private static String text(rp1.rossum.event.RsSensorEvent e) {
        if (e instanceof RsRangeSensorEvent) {
            RsRangeSensorEvent r = (RsRangeSensorEvent) e;
            return java.util.Arrays.toString(new Object[] {r.status, bits(r.x), bits(r.y), bits(r.range),
                r.getNameOfObjectDetected()});
        }
        RsTargetSensorEvent t = (RsTargetSensorEvent) e;
        return java.util.Arrays.toString(new Object[] {t.status, bits(t.x), bits(t.y), bits(t.ux), bits(t.uy),
            bits(t.xDetection), bits(t.yDetection), bits(t.range), bits(t.bearing)});
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    /** A sensor whose sight angle its own class changes between readings looks the new way at once. */
    @Test
    void aSensorTurnedBetweenReadingsAtTheSamePoseLooksTheNewWay() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "north wall", -1, 2.0, 1, 2.1);
        class Turret extends RsBodyRangeSensor {
            private static final long serialVersionUID = 1L;

            Turret() {
                super(HEAD, 4, 0, 0, 0, 4.0, 4);
            }

            void aim(double angle) {
                sightAngle = angle;
            }
        }
        Turret s = new Turret();
        RsTransform pose = TestPlans.pose(0, 0, 0);
        s.computeAndSetState(1.0, plan, pose);
        assertEquals(false, event(s).status, "looking east, along the wall");
        s.aim(Math.PI / 2);
        s.computeAndSetState(2.0, plan, pose);
        assertEquals(true, event(s).status, "looking north, at it");
        assertEquals(2.0, event(s).range, EPS);
    }
}
