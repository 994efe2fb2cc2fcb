package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.request.RsMotionRequest;

/** Interpretation of motion requests and analytic poses (behavior.md sections 5.2 and 5.7). */
class MotionTest {
    private static final double EPS = 1e-9;

    /** A body at (x, y, theta) at time 0 that starts the request at time 1. */
    private static RsBody started(double x, double y, double theta, double v, double w, double duration) {
        RsBody body = new RsBody("b");
        body.addPart(new RsBodyCircle(0, 0, 0.1));
        body.place(0.0, x, y, theta);
        body.computeMotion(1.0, new RsMotionRequest(v, w, duration));
        return body;
    }

    @Test
    void aStraightLineMovesAlongTheHeadingKeepingIt() {
        RsBody b = started(1, 1, Math.PI / 2, 0.5, 0.0, 4.0);
        assertInstanceOf(RsMotionLine.class, b.motion);
        RsPositionEvent p = b.getPositionEvent(3.0);
        assertEquals(1.0, p.x, EPS);
        assertEquals(2.0, p.y, EPS);
        assertEquals(Math.PI / 2, p.orientation, EPS);
        assertEquals(0.5, p.velocity);
        assertEquals(0.0, p.turnRate);
    }

    @Test
    void backingMovesOppositeToTheHeadingAndReportsNegativeVelocity() {
        RsBody b = started(0, 0, 0, -0.5, 0.0, 2.0);
        RsPositionEvent p = b.getPositionEvent(3.0);
        assertEquals(-1.0, p.x, EPS);
        assertEquals(0.0, p.orientation, EPS);
        assertEquals(-0.5, p.velocity);
    }

    @Test
    void poseIsClampedToTheEndOfTheMotion() {
        RsBody b = started(0, 0, 0, 1.0, 0.0, 2.0);
        assertEquals(2.0, b.getPositionEvent(10.0).x, EPS);
        assertEquals(0.0, b.getPositionEvent(0.5).x, EPS);
    }

    @Test
    void aForwardLeftArcTurnsAboutAPivotToTheLeft() {
        RsBody b = started(0, 0, 0, 1.0, 1.0, Math.PI / 2);
        assertInstanceOf(RsMotionCircle.class, b.motion);
        assertEquals(0.0, ((RsMotionCircle) b.motion).getPivot().x, EPS);
        assertEquals(1.0, ((RsMotionCircle) b.motion).getPivot().y, EPS);
        RsPositionEvent p = b.getPositionEvent(1.0 + Math.PI / 2);
        assertEquals(1.0, p.x, EPS);
        assertEquals(1.0, p.y, EPS);
        assertEquals(Math.PI / 2, p.orientation, EPS);
        assertEquals(1.0, p.turnRate, EPS);
        assertEquals(1.0, p.velocity, EPS);
    }

    @Test
    void aForwardRightTurnReportsNegativeVelocity() {
        RsBody b = started(0, 0, 0, 1.0, -0.5, 1.0);
        RsPositionEvent p = b.getPositionEvent(1.5);
        assertEquals(-0.5, p.turnRate, EPS);
        assertEquals(-1.0, p.velocity, EPS);
    }

    @Test
    void aReversingArcTurnsTheHeadingAgainstTheRequestedRate() {
        RsBody b = started(0, 0, 0, -0.5, 0.5, 1.0);
        RsPositionEvent p = b.getPositionEvent(2.0);
        assertEquals(-0.5, p.orientation, EPS);
        assertEquals(-0.5, p.turnRate, EPS);
        RsPoint pivot = ((RsMotionCircle) b.motion).getPivot();
        assertEquals(0.0, pivot.x, EPS);
        assertEquals(1.0, pivot.y, EPS);
        assertEquals(-Math.sin(0.5), p.x, EPS);
        assertEquals(1.0 - Math.cos(0.5), p.y, EPS);
    }

    @Test
    void aPivotStaysInPlaceAndReportsZeroVelocity() {
        RsBody b = started(2, 3, 0, 0.0, Math.PI / 2, 1.0);
        RsPositionEvent p = b.getPositionEvent(2.0);
        assertEquals(2.0, p.x, EPS);
        assertEquals(3.0, p.y, EPS);
        assertEquals(Math.PI / 2, p.orientation, EPS);
        assertEquals(0.0, p.velocity, EPS);
    }

    @Test
    void orientationIsReportedWithinMinusPiToPi() {
        RsBody b = started(0, 0, 3.9269908169872414, 0.0, 0.0, 0.0);
        assertEquals(3.9269908169872414 - 2 * Math.PI, b.getPositionEvent(1.0).orientation, EPS);
    }

    @Test
    void shortOrSpeedlessRequestsAreNullMotions() {
        assertInstanceOf(RsMotionNull.class, started(0, 0, 0, 1.0, 1.0, 0.00009).motion);
        assertInstanceOf(RsMotionNull.class, started(0, 0, 0, 0.00009, -0.00009, 10.0).motion);
        assertInstanceOf(RsMotionLine.class, started(0, 0, 0, 0.0001, 0.0, 10.0).motion);
        assertInstanceOf(RsMotionLine.class, started(0, 0, 0, 0.0, 0.0001, 10.0).motion);
        assertInstanceOf(RsMotionCircle.class, started(0, 0, 0, 0.0, 0.01, 10.0).motion);
    }

    @Test
    void turnRatesBelowATenthOfADegreePerSecondAreStraight() {
        double limit = 0.1 * Math.PI / 180;
        assertInstanceOf(RsMotionLine.class, started(0, 0, 0, 1.0, limit * 0.99, 1.0).motion);
        assertInstanceOf(RsMotionCircle.class, started(0, 0, 0, 1.0, limit, 1.0).motion);
    }

    @Test
    void aNullMotionReportsZeroVelocityAndTurnRate() {
        RsBody b = started(1, 2, 0.5, 0.0, 0.0, 1.0);
        RsPositionEvent p = b.getPositionEvent(5.0);
        assertEquals(1.0, p.x, EPS);
        assertEquals(0.5, p.orientation, EPS);
        assertEquals(0.0, p.velocity);
        assertEquals(0.0, p.turnRate);
    }

    @Test
    void beforeAnyPlacementThePositionIsTheOrigin() {
        RsPositionEvent p = new RsBody("unplaced").getPositionEvent(4.0);
        assertEquals(4.0, p.simTime);
        assertEquals(0.0, p.x);
        assertEquals(0.0, p.orientation);
    }

    @Test
    void aNewMotionStartsWhereThePreviousOneIsAtThatTime() {
        RsBody b = started(0, 0, 0, 1.0, 0.0, 10.0);
        b.computeMotion(3.0, new RsMotionRequest(0.0, Math.PI / 2, 1.0));
        RsPositionEvent p = b.getPositionEvent(4.0);
        assertEquals(2.0, p.x, EPS);
        assertEquals(Math.PI / 2, p.orientation, EPS);
    }

    @Test
    void setTimeMovesTheCurrentPoseAndTellsWhetherTheMotionGoesOn() {
        RsMotion m = started(0, 0, 0, 1.0, 0.0, 2.0).motion;
        assertEquals(true, m.setTime(2.0));
        assertEquals(1.0, m.getPosition().x, EPS);
        assertEquals(false, m.setTime(3.0));
        assertEquals(3.0, m.getTime());
        assertEquals(false, m.setTimeForward(2.5));
        assertEquals(3.0, m.getTime());
    }

    @Test
    void stoppingAMotionEndsItThere() {
        RsMotion m = started(0, 0, 0, 1.0, 0.0, 10.0).motion;
        m.setTime(2.0);
        m.stopMotionAtTime(2.5);
        assertEquals(1.5, m.timeTotal, EPS);
        assertEquals(2.5, m.time1, EPS);
        assertEquals(1.5, m.getPoseAtTime(100).m13, EPS);
    }

    @Test
    void continuingMotionsShareASeriesAndAPlacementStartsANewOne() {
        RsBody b = started(0, 0, 0, 1.0, 0.0, 10.0);
        RsMotion first = b.motion;
        b.computeMotion(2.0, new RsMotionRequest(1.0, 1.0, 1.0));
        assertEquals(first.getContinuitySeriesID(), b.motion.getContinuitySeriesID());
        assertNotEquals(first.getContinuityID(), b.motion.getContinuityID());
        b.place(3.0, 0, 0, 0);
        assertNotEquals(first.getContinuitySeriesID(), b.motion.getContinuitySeriesID());
    }

    @Test
    void motionIdsCountAlongTheRobotsMotionsSoEveryRunNumbersThemAlike() {
        int[][] runs = new int[2][];
        for (int run = 0; run < 2; run++) {
            RsBody b = started(0, 0, 0, 1.0, 0.0, 10.0);
            b.computeMotion(2.0, new RsMotionRequest(1.0, 1.0, 1.0));
            int continued = b.motion.getContinuityID();
            b.place(3.0, 0, 0, 0);
            runs[run] = new int[] {continued, b.motion.getContinuityID(), b.motion.getContinuitySeriesID()};
            RsMotion.getNewContinuityID();
        }
        assertArrayEquals(runs[0], runs[1]);
    }

    @Test
    void motionDepictionGivesThePointsVelocity() {
        RsMotion m = started(0, 0, 0, 0.0, 1.0, 10.0).motion;
        RsMotionDepiction d = m.getMotionDepictionAtBodyPoint(0.0, 0.5);
        assertEquals(-0.5, d.getVelocity().x, EPS);
        assertEquals(-0.5, d.getSignedSpeed(), EPS);
        assertEquals(true, d.isMoving());
    }

    /**
     * A pose written into a transform of the caller's is the pose a new transform gets, to the bit, for
     * lines, arcs, turns in place and stops, before, during and after the motion; and an arc's is the
     * start pose rotated about the pivot as {@link RsTransform#rotationAbout} and the product of two
     * transforms compute it.
     */
    @Test
    void aPoseWrittenInPlaceIsTheSameToTheBit() {
        double[][] requests = {{0.5, 0.0}, {-0.3, 0.0}, {0.4, 1.3}, {0.2, -2.1}, {0.0, 2.0}, {0.0, 0.0}};
        RsTransform into = new RsTransform();
        for (double[] q : requests) {
            RsBody b = started(1.25, -3.5, 0.7, q[0], q[1], 2.5);
            RsMotion m = b.motion;
            for (double t = 0.0; t < 5.0; t += 0.0371) {
                RsTransform fresh = m.getPoseAtTime(t);
                m.getPoseAtTime(t, into);
                assertArrayEquals(bits(fresh), bits(into), m + " at " + t);
                if (m instanceof RsMotionCircle c) {
                    double angle = c.getTurnRate() * (Math.max(m.time0, Math.min(t, m.time1)) - m.time0);
                    RsPoint pivot = c.getPivot();
                    RsTransform before = new RsTransform(RsTransform.rotationAbout(angle, pivot.x, pivot.y), m.transform0);
                    assertArrayEquals(bits(before), bits(into), m + " at " + t);
                }
            }
        }
    }

    private static long[] bits(RsTransform p) {
        return new long[] {Double.doubleToRawLongBits(p.m11), Double.doubleToRawLongBits(p.m12),
                Double.doubleToRawLongBits(p.m13), Double.doubleToRawLongBits(p.m21),
                Double.doubleToRawLongBits(p.m22), Double.doubleToRawLongBits(p.m23)};
    }
}
