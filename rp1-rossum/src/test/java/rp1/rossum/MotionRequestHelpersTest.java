package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import rp1.rossum.request.RsMotionRequest;

/** The client-side goal helpers of wheel systems (behavior.md section 5.6). */
class MotionRequestHelpersTest {
    private static final double EPS = 1e-12;
    private final RsWheelSystem wheels = new RsDifferentialSteering(0.3, 0.05);

    /** Where the robot ends when the simulator executes {@code r} from the origin, heading 0. */
    private static RsTransform endPose(RsMotionRequest r) {
        RsMotion m = MotionRequests.motionFor(null, 0.0, r);
        return m.getPoseAtTime(r.duration);
    }

    @Test
    void aGoalStraightAheadIsAStraightLine() {
        RsMotionRequest r = wheels.getMotionRequest(1.0, 0.0, 0.5);
        assertEquals(0.5, r.linearVelocity, EPS);
        assertEquals(0.0, r.rotationalVelocity, EPS);
        assertEquals(2.0, r.duration, EPS);
    }

    @Test
    void aGoalBehindIsReachedBackingAtTheSameSpeedWhateverItsSign() {
        RsMotionRequest r = wheels.getMotionRequest(-1.0, 0.0, -0.5);
        assertEquals(-0.5, r.linearVelocity, EPS);
        assertEquals(2.0, r.duration, EPS);
    }

    @Test
    void aGoalToTheFrontLeftIsAQuarterCircleOfRadiusOne() {
        RsMotionRequest r = wheels.getMotionRequest(1.0, 1.0, 0.5);
        assertEquals(0.5, r.linearVelocity, EPS);
        assertEquals(Math.PI / 2 / 0.5, r.duration, EPS);
        assertEquals(0.5, r.rotationalVelocity, EPS);
        RsTransform end = endPose(r);
        assertEquals(1.0, end.m13, 1e-9);
        assertEquals(1.0, end.m23, 1e-9);
        assertEquals(Math.PI / 2, end.getTheta(), 1e-9);
    }

    @Test
    void aGoalToTheFrontRightTurnsClockwiseThroughTheGoal() {
        RsMotionRequest r = wheels.getMotionRequest(2.0, -1.0, 1.0);
        assertEquals(true, r.rotationalVelocity < 0);
        RsTransform end = endPose(r);
        assertEquals(2.0, end.m13, 1e-9);
        assertEquals(-1.0, end.m23, 1e-9);
    }

    @Test
    void aGoalToTheRearLeftIsReachedBackingAlongTheArc() {
        RsMotionRequest r = wheels.getMotionRequest(-1.0, 1.0, 0.5);
        assertEquals(-0.5, r.linearVelocity, EPS);
        assertEquals(true, r.rotationalVelocity > 0);
        RsTransform end = endPose(r);
        assertEquals(-1.0, end.m13, 1e-9);
        assertEquals(1.0, end.m23, 1e-9);
        assertEquals(-Math.PI / 2, end.getTheta(), 1e-9);
    }

    @Test
    void anArcWiderThan1000MetresBecomesAStraightLine() {
        RsMotionRequest r = wheels.getMotionRequest(1.0, 0.0001, 1.0);
        assertEquals(0.0, r.rotationalVelocity);
        assertEquals(1.0, r.duration, EPS);
    }

    @Test
    void noRequestForAStandstillSpeedOrANearbyGoal() {
        assertNull(wheels.getMotionRequest(1.0, 1.0, 1e-7));
        assertNull(wheels.getMotionRequest(0.01, 0.01, 1.0));
        assertNull(wheels.getMotionRequest(0.0, 0.0, 1.0));
    }

    @Test
    void noRequestForAMotionShorterThanOneMillisecond() {
        assertNull(wheels.getMotionRequest(0.0009, 0.0, 1.0));
        assertEquals(0.001, wheels.getMotionRequest(0.001, 0.0, 1.0).duration, EPS);
    }

    @Test
    void pivotTurnsAtNinetyDegreesPerSecondWhateverTheSpeed() {
        RsMotionRequest left = wheels.getMotionRequestForPivot(0.0, 1.0, 25.0);
        assertEquals(0.0, left.linearVelocity);
        assertEquals(Math.PI / 2, left.rotationalVelocity, EPS);
        assertEquals(1.0, left.duration, EPS);
        RsMotionRequest right = wheels.getMotionRequestForPivot(1.0, -1.0, 0.1);
        assertEquals(-Math.PI / 2, right.rotationalVelocity, EPS);
        assertEquals(0.5, right.duration, EPS);
    }

    @Test
    void pivotToFaceBackwardsTakesTwoSeconds() {
        RsMotionRequest r = wheels.getMotionRequestForPivot(-1.0, 0.0, 1.0);
        assertEquals(2.0, r.duration, EPS);
    }

    @Test
    void noPivotForATurnShorterThanOneMillisecond() {
        assertNull(wheels.getMotionRequestForPivot(1.0, 0.001, 1.0));
        assertNull(wheels.getMotionRequestForPivot(1.0, 0.0, 1.0));
    }

    @Test
    void ackermanSteeringCannotSeekGoalsOrPivot() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        assertNull(a.getMotionRequest(1.0, 1.0, 1.0));
        assertNull(a.getMotionRequestForPivot(0.0, 1.0, 1.0));
    }
}
