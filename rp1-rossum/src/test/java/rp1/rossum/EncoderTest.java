package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Wheel encoders (behavior.md section 5.8). The wheels here have radius 0.1 m and 4 intervals
 * (pi/2 rad each), so a hub speed of 0.1 m/s turns the wheel 1 rad per second.
 */
class EncoderTest {
    private static final double EPS = 1e-12;

    private static RsWheel wheel(double x, double y) {
        RsWheel w = new RsWheel(TestPlans.rect(x - 0.1, y - 0.01, x + 0.1, y + 0.01), 4, x, y, 0.1);
        w.addEncoder(4);
        return w;
    }

    private static RsMotion straight(double v) {
        return MotionRequests.motionFor(null, 0.0, new RsMotionRequest(v, 0.0, 100.0));
    }

    /** Evaluates the wheel at each of the given times of the motion. */
    private static void evaluate(RsWheel w, RsMotion m, double... times) {
        for (double t : times) {
            m.setTime(t);
            w.applyMotion(m);
        }
    }

    @Test
    void addEncoderReturnsTheWheelOrNullForNoIntervals() {
        RsWheel w = new RsWheel(TestPlans.rect(0, 0, 1, 1), 4, 0, 0, 0.1);
        assertNull(w.addEncoder(0));
        assertNull(w.addEncoder(-3));
        assertSame(w, w.addEncoder(8));
        assertEquals(8, w.getEncoderIntervalCount());
    }

    @Test
    void theFirstEvaluationFromRestCountsNothing() {
        RsWheel w = wheel(0, 0.2);
        evaluate(w, straight(0.1), 0.0);
        RsEncoderStatusEvent e = w.getEncoderStatusEvent(0.0, 1, false);
        assertEquals(0, e.accumulatorValue);
        assertEquals(0, e.quadratureValue);
    }

    @Test
    void accumulatorCountsIntervalBoundariesCrossed() {
        RsWheel w = wheel(0, 0.2);
        evaluate(w, straight(0.1), 0.0, 1.0);
        RsEncoderStatusEvent e = w.getEncoderStatusEvent(1.0, 1, false);
        assertEquals(1, e.accumulatorValue);
        assertEquals(1, e.absoluteAccumulatorValue);
        assertEquals(1, e.quadratureValue);
        assertEquals(1, e.encoderInterval);
        assertEquals(1.0, e.encoderAngle, EPS);
    }

    @Test
    void angleWrapsAfterAFullTurnWhileTheAccumulatorKeepsCounting() {
        RsWheel w = wheel(0, 0.2);
        evaluate(w, straight(0.1), 0.0, 1.0, 2.0, 7.0, 8.0);
        RsEncoderStatusEvent e = w.getEncoderStatusEvent(8.0, 1, false);
        assertEquals(5, e.accumulatorValue);
        assertEquals(8.0 - 2 * Math.PI, e.encoderAngle, 1e-9);
        assertEquals(1, e.encoderInterval);
    }

    @Test
    void backingCountsDownWithNegativeQuadrature() {
        RsWheel w = wheel(0, 0.2);
        evaluate(w, straight(-0.1), 0.0, 1.0);
        RsEncoderStatusEvent e = w.getEncoderStatusEvent(1.0, 1, false);
        assertEquals(-1, e.accumulatorValue);
        assertEquals(1, e.absoluteAccumulatorValue);
        assertEquals(-1, e.quadratureValue);
        assertEquals(2 * Math.PI - 1.0, e.encoderAngle, 1e-9);
        assertEquals(3, e.encoderInterval);
    }

    @Test
    void inAPivotTheLeftWheelTurnsBackwardsAndTheRightForwards() {
        RsWheel left = wheel(0, 0.1);
        RsWheel right = wheel(0, -0.1);
        RsMotion pivot = MotionRequests.motionFor(null, 0.0, new RsMotionRequest(0.0, 1.0, 10.0));
        evaluate(left, pivot, 0.0, 1.0);
        evaluate(right, pivot, 0.0, 1.0);
        assertEquals(-1, left.getEncoderStatusEvent(1, 1, false).quadratureValue);
        assertEquals(1, right.getEncoderStatusEvent(1, 1, false).quadratureValue);
    }

    @Test
    void theLastIntervalIsCountedAtTheEndThenTheWheelRests() {
        RsWheel w = wheel(0, 0.2);
        RsMotion m = MotionRequests.motionFor(null, 0.0, new RsMotionRequest(0.1, 0.0, 2.0));
        evaluate(w, m, 0.0, 1.0, 2.0, 5.0);
        assertEquals(1, w.getEncoderStatusEvent(5, 1, false).accumulatorValue);
        assertEquals(2.0, w.getEncoderStatusEvent(5, 1, false).encoderAngle, EPS);
    }

    @Test
    void clearOnReportZeroesTheAccumulatorsAfterReporting() {
        RsWheel w = wheel(0, 0.2);
        evaluate(w, straight(0.1), 0.0, 1.0);
        RsEncoderStatusEvent first = w.getEncoderStatusEvent(1.0, 7, true);
        assertEquals(1, first.accumulatorValue);
        assertEquals(7, first.requestIndex);
        assertEquals(w.getID(), first.encoderID);
        assertEquals(true, first.clearOnReport);
        RsEncoderStatusEvent second = w.getEncoderStatusEvent(1.0, 8, false);
        assertEquals(0, second.accumulatorValue);
        assertEquals(0, second.absoluteAccumulatorValue);
        assertEquals(1, second.encoderInterval);
    }

    @Test
    void accumulatorMapsToTheDistanceTheHubTravelled() {
        RsWheel w = wheel(0, 0.2);
        assertEquals(2 * Math.PI * 0.1, w.mapAccumulatorToDisplacement(4), EPS);
        assertEquals(-Math.PI / 2 * 0.1, w.mapAccumulatorToDisplacement(-1), EPS);
    }

    @Test
    void aWheelWithoutAnEncoderCountsNothing() {
        RsWheel w = new RsWheel(TestPlans.rect(-0.1, 0.19, 0.1, 0.21), 4, 0, 0.2, 0.1);
        evaluate(w, straight(0.1), 0.0, 1.0, 2.0);
        assertEquals(0, w.getEncoderStatusEvent(2.0, 1, false).absoluteAccumulatorValue);
        assertEquals(0.0, w.mapAccumulatorToDisplacement(3));
    }

    @Test
    void aCasterSwivelsToItsDirectionOfTravel() {
        RsWheelCaster c = new RsWheelCaster(TestPlans.rect(-0.05, -0.01, 0.05, 0.01), 4, -0.2, 0.0);
        evaluate(c, straight(-0.1), 0.0, 1.0);
        assertEquals(Math.PI, Math.abs(c.getSteeringAngle()), 1e-9);
        c.resetStateData();
        assertEquals(0.0, c.getSteeringAngle());
    }

    @Test
    void theBodyBringsItsWheelSystemsEncodersUpToDate() {
        RsBody body = new RsBody("encoders");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.4, 0.1);
        ds.addDefaultWheels(0.1, 0.02);
        RsEncoder[] enc = ds.addEncodersToDefaultWheels(4);
        body.addPart(ds);
        body.place(0.0, 0, 0, 0);
        body.computeMotion(0.0, new RsMotionRequest(0.1, 0.0, 10.0));
        for (double t : new double[] {0.0, 1.0}) {
            body.motion.setTime(t);
            body.applyMotion();
        }
        assertEquals(1, ((RsWheel) enc[0]).getEncoderStatusEvent(1, 1, false).accumulatorValue);
        assertEquals(1, ((RsWheel) enc[1]).getEncoderStatusEvent(1, 1, false).accumulatorValue);
    }
}
