package rp1.simulator.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;

/** Range and target readings as a noisy robot's client gets them. */
class SensorNoiseTest {
    private static final double[] HEAD = {-0.02, -0.02, 0.02, -0.02, 0.02, 0.02, -0.02, 0.02};
    private static final int N = 50_000;

    private static NoiseSettings settings(double rangeSigma, double dropout, double targetRange, double bearing) {
        return new NoiseSettings(rangeSigma, dropout, targetRange, bearing, 0, 0, 0);
    }

    /** A range sensor 2 m from a wall ahead, its state computed. */
    private static RsBodyRangeSensor rangeSensorBeforeAWall() {
        RsPlan plan = new RsPlan();
        RsWall w = new RsWall("wall", plan);
        w.setGeometry(new double[] {2.0, -1.0, 3.0, -1.0, 3.0, 1.0, 2.0, 1.0});
        plan.addObject(w);
        RsBodyRangeSensor s = new RsBodyRangeSensor(HEAD, 4, 0, 0, 0, 5.0, 50);
        s.computeAndSetState(1.0, plan, new RsTransform(0, 0, 0));
        return s;
    }

    /** A target sensor seeing a candle 2 m ahead, its state computed. */
    private static RsBodyTargetSensor targetSensorBeforeACandle() {
        RsPlan plan = new RsPlan();
        RsTarget t = new RsTarget("candle", plan);
        t.setGeometry(new double[] {2.0, 0.0, 0.05});
        plan.addObject(t);
        RsBodyTargetSensor s = new RsBodyTargetSensor(HEAD, 4, 0, 0, 0, Math.PI / 2, 4.0, 3, 4);
        s.computeAndSetState(1.0, plan, new RsTransform(0, 0, 0));
        return s;
    }

    @Test
    void rangesScatterAboutTheTruthWithTheAskedSigma() {
        RsBodyRangeSensor s = rangeSensorBeforeAWall();
        SensorNoise noise = new SensorNoise(settings(0.03, 0, 0, 0), 11L, 1);
        double sum = 0;
        double squares = 0;
        for (int i = 0; i < N; i++) {
            RsRangeSensorEvent e = (RsRangeSensorEvent) noise.reading(s, 1.0, true);
            assertTrue(e.status);
            assertEquals("wall", e.getNameOfObjectDetected());
            double err = e.range - 2.0;
            sum += err;
            squares += err * err;
        }
        assertEquals(0.0, sum / N, 0.001);
        assertEquals(0.03, Math.sqrt(squares / N), 0.0005);
    }

    @Test
    void readingsAreLostAtTheDropoutRateAndThenSeeNothing() {
        RsBodyRangeSensor s = rangeSensorBeforeAWall();
        SensorNoise noise = new SensorNoise(settings(0, 0.2, 0, 0), 12L, 1);
        int lost = 0;
        for (int i = 0; i < N; i++) {
            RsRangeSensorEvent e = (RsRangeSensorEvent) noise.reading(s, 1.0, true);
            if (!e.status) {
                lost++;
                assertEquals(0.0, e.range);
                assertEquals("", e.getNameOfObjectDetected());
            } else {
                assertEquals(2.0, e.range, 1e-12);
            }
        }
        assertEquals(0.2, lost / (double) N, 0.006);
    }

    @Test
    void aReadingKeepsItsErrorUntilItChanges() {
        RsBodyRangeSensor s = rangeSensorBeforeAWall();
        SensorNoise noise = new SensorNoise(settings(0.5, 0, 0, 0), 13L, 1);
        RsRangeSensorEvent first = (RsRangeSensorEvent) noise.reading(s, 1.0, true);
        RsRangeSensorEvent asked = (RsRangeSensorEvent) noise.reading(s, 2.0, false);
        assertEquals(first.range, asked.range);
        assertEquals(2.0, asked.simTime);
        RsRangeSensorEvent next = (RsRangeSensorEvent) noise.reading(s, 3.0, true);
        assertTrue(next.range != first.range);
    }

    @Test
    void noisyRangesStayWithinTheSensorsReach() {
        RsBodyRangeSensor s = rangeSensorBeforeAWall();
        SensorNoise noise = new SensorNoise(settings(10.0, 0, 0, 0), 14L, 1);
        for (int i = 0; i < 1000; i++) {
            double r = ((RsRangeSensorEvent) noise.reading(s, 1.0, true)).range;
            assertTrue(r >= 0.0 && r <= 5.0, "range " + r);
        }
    }

    @Test
    void targetRangeAndBearingScatterWithTheirOwnSigmas() {
        RsBodyTargetSensor s = targetSensorBeforeACandle();
        SensorNoise noise = new SensorNoise(settings(0, 0, 0.1, Math.toRadians(2)), 15L, 1);
        double rangeSquares = 0;
        double bearingSquares = 0;
        for (int i = 0; i < N; i++) {
            RsTargetSensorEvent e = (RsTargetSensorEvent) noise.reading(s, 1.0, true);
            rangeSquares += (e.range - 2.0) * (e.range - 2.0);
            bearingSquares += e.bearing * e.bearing;
            assertEquals(e.range * Math.cos(e.bearing), e.xDetection, 1e-12);
            assertEquals(e.range * Math.sin(e.bearing), e.yDetection, 1e-12);
            assertEquals("candle", e.getNameOfObjectDetected());
        }
        assertEquals(0.1, Math.sqrt(rangeSquares / N), 0.002);
        assertEquals(Math.toRadians(2), Math.sqrt(bearingSquares / N), Math.toRadians(0.04));
    }

    @Test
    void withoutNoiseTheReadingIsTheSensorsOwn() {
        RsBodyRangeSensor s = rangeSensorBeforeAWall();
        RsRangeSensorEvent e = (RsRangeSensorEvent) RobotNoise.NONE.reading(s, 1.0, true);
        assertEquals(2.0, e.range, 1e-12);
        assertSame(RobotNoise.NONE, new Noise(NoiseSettings.OFF, 3L).forRobot(1));
    }
}
