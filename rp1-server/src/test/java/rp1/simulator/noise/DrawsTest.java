package rp1.simulator.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;
import rp1.simulator.noise.Draws.Quantity;

/** The random streams noise is drawn from: their statistics, and that one seed gives one sequence. */
class DrawsTest {
    private static final int N = 200_000;

    @Test
    void gaussianDrawsHaveMeanZeroAndTheAskedSigma() {
        Draws d = new Draws(42L, 1, Quantity.RANGE);
        double sum = 0;
        double squares = 0;
        for (int i = 0; i < N; i++) {
            double x = d.gaussian(0.05);
            sum += x;
            squares += x * x;
        }
        double mean = sum / N;
        double sigma = Math.sqrt(squares / N - mean * mean);
        assertEquals(0.0, mean, 0.05 * 5 / Math.sqrt(N));
        assertEquals(0.05, sigma, 0.05 * 0.01);
    }

    @Test
    void aboutTwoThirdsOfGaussianDrawsLieWithinOneSigma() {
        Draws d = new Draws(7L, 3, Quantity.TARGET_BEARING);
        int within = 0;
        for (int i = 0; i < N; i++) {
            if (Math.abs(d.gaussian(2.0)) < 2.0) {
                within++;
            }
        }
        assertEquals(0.6827, within / (double) N, 0.005);
    }

    @Test
    void chancesAndBinomialsHappenAtTheAskedRate() {
        Draws d = new Draws(1L, 1, Quantity.DROPOUT);
        int hits = 0;
        for (int i = 0; i < N; i++) {
            if (d.chance(0.1)) {
                hits++;
            }
        }
        assertEquals(0.1, hits / (double) N, 0.003);
        long missed = 0;
        for (int i = 0; i < 1000; i++) {
            missed += d.binomial(200, 0.02);
        }
        assertEquals(0.02, missed / 200_000.0, 0.002);
    }

    @Test
    void oneSeedRobotAndQuantityGiveOneSequence() {
        Draws a = new Draws(99L, 2, Quantity.SLIP_TURN);
        Draws b = new Draws(99L, 2, Quantity.SLIP_TURN);
        for (int i = 0; i < 100; i++) {
            assertEquals(a.gaussian(1.0), b.gaussian(1.0));
        }
    }

    @Test
    void anotherSeedRobotOrQuantityGivesAnotherSequence() {
        double first = new Draws(99L, 2, Quantity.SLIP_TURN).uniform();
        assertNotEquals(first, new Draws(100L, 2, Quantity.SLIP_TURN).uniform());
        assertNotEquals(first, new Draws(99L, 3, Quantity.SLIP_TURN).uniform());
        assertNotEquals(first, new Draws(99L, 2, Quantity.SLIP_DISTANCE).uniform());
    }

    @Test
    void aZeroSigmaOrProbabilityDrawsNothing() {
        Draws d = new Draws(5L, 1, Quantity.ENCODER);
        assertEquals(0.0, d.gaussian(0.0));
        assertEquals(false, d.chance(0.0));
        assertEquals(0, d.binomial(1000, 0.0));
        assertEquals(new Draws(5L, 1, Quantity.ENCODER).uniform(), d.uniform());
    }
}
