package rp1.simulator.noise;

import java.util.SplittableRandom;


/**
 * One stream of random draws for one quantity of one robot. Its seed is derived from the run's seed,
 * the robot's number and the quantity alone, so its draws depend on nothing but the order of the
 * simulation's own events that ask for them: not on other robots, other quantities, threads, or the
 * world's random source (which picks random targets and placements and is never drawn from here).
 *
 * <p>The Gaussian is computed here with {@link StrictMath}, not taken from the JDK's
 * {@code nextGaussian}, so that a recording replays to the same numbers on any Java version.
 */
final class Draws {
    private final SplittableRandom random;

    Draws(long runSeed, int robot, Quantity quantity) {
        random = new SplittableRandom(seed(runSeed, robot, quantity));
    }

    /** The seed of one stream: the run seed, robot number and quantity mixed (SplitMix64's finaliser). */
    static long seed(long runSeed, int robot, Quantity quantity) {
        long s = runSeed;
        s = SplitMix.mix(s + 0x9E3779B97F4A7C15L * (robot + 1L));
        s = SplitMix.mix(s + 0xC2B2AE3D27D4EB4FL * (quantity.ordinal() + 1L));
        return s;
    }

    /** A uniform draw in [0, 1). */
    double uniform() {
        return random.nextDouble();
    }

    /** Whether an event of probability {@code p} happens; nothing is drawn when p is 0. */
    boolean chance(double p) {
        return p > 0.0 && random.nextDouble() < p;
    }

    /** A normal draw with mean 0 and standard deviation {@code sigma}; nothing is drawn when sigma is 0. */
    double gaussian(double sigma) {
        if (sigma == 0.0) {
            return 0.0;
        }
        // Marsaglia's polar method; the second value is dropped so that a draw is one call.
        double u;
        double v;
        double s;
        do {
            u = 2.0 * random.nextDouble() - 1.0;
            v = 2.0 * random.nextDouble() - 1.0;
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        return sigma * u * StrictMath.sqrt(-2.0 * StrictMath.log(s) / s);
    }

    /** How many of {@code n} independent events of probability {@code p} happen (0 when p is 0). */
    int binomial(int n, double p) {
        if (p == 0.0) {
            return 0;
        }
        int k = 0;
        for (int i = 0; i < n; i++) {
            if (random.nextDouble() < p) {
                k++;
            }
        }
        return k;
    }

    /** The quantities that draw, each from a stream of its own. */
    enum Quantity {
        RANGE, DROPOUT, TARGET_RANGE, TARGET_BEARING, ENCODER, SLIP_DISTANCE, SLIP_TURN
    }
}
