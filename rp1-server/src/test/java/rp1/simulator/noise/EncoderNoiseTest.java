package rp1.simulator.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsEncoderStatusEvent;

/** Encoders that miss counts. */
class EncoderNoiseTest {
    private static EncoderNoise encoders(double miss) {
        return new EncoderNoise(new NoiseSettings(0, 0, 0, 0, miss, 0, 0), 21L, 1);
    }

    private static RsEncoderStatusEvent truth(int signed, int absolute, boolean clear) {
        return new RsEncoderStatusEvent(1.0, 0, 7, signed, absolute, 1, 3, 0.5, clear);
    }

    @Test
    void countsAreMissedAtTheAskedRate() {
        RsEncoderStatusEvent seen = encoders(0.05).report(truth(100_000, 100_000, false));
        assertEquals(0.95 * 100_000, seen.absoluteAccumulatorValue, 300);
        assertEquals(seen.absoluteAccumulatorValue, seen.accumulatorValue);
        assertEquals(3, seen.encoderInterval);
        assertEquals(0.5, seen.encoderAngle);
    }

    @Test
    void missedCountsStayMissedUntilTheAccumulatorsAreCleared() {
        EncoderNoise e = encoders(0.1);
        RsEncoderStatusEvent first = e.report(truth(1000, 1000, false));
        RsEncoderStatusEvent again = e.report(truth(1000, 1000, false));
        assertEquals(first.accumulatorValue, again.accumulatorValue);
        RsEncoderStatusEvent more = e.report(truth(2000, 2000, true));
        assertTrue(more.accumulatorValue - first.accumulatorValue < 1000);
        RsEncoderStatusEvent afterClear = e.report(truth(0, 0, false));
        assertEquals(0, afterClear.accumulatorValue);
        assertEquals(0, afterClear.absoluteAccumulatorValue);
    }

    @Test
    void backwardsCountsAreMissedBackwards() {
        RsEncoderStatusEvent seen = encoders(0.1).report(truth(-1000, 1000, false));
        assertTrue(seen.accumulatorValue > -1000 && seen.accumulatorValue < -800, "" + seen.accumulatorValue);
        assertEquals(-seen.accumulatorValue, seen.absoluteAccumulatorValue);
    }
}
