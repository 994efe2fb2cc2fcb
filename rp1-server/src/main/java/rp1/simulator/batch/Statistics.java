package rp1.simulator.batch;

/**
 * What a sample of numbers says: how many, mean, sample standard deviation (n - 1), the half-width of
 * the 95 % confidence interval of the mean (Student's t with n - 1 degrees of freedom), min and max.
 * NaN where a sample is too small to say (no values; the deviation and interval of one value).
 *
 * @param n    how many values
 * @param mean their mean
 * @param sd   their sample standard deviation
 * @param ci95 the mean's 95 % confidence interval is {@code mean ± ci95}
 * @param min  the least
 * @param max  the greatest
 */
public record Statistics(int n, double mean, double sd, double ci95, double min, double max) {
    /** Two-sided 95 % quantiles of Student's t (its 97.5th percentile) for 1 to 30 degrees of freedom. */
    private static final double[] T975 = {12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622,
        2.2281, 2.2010, 2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860, 2.0796, 2.0739,
        2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
    /** The normal distribution's 97.5th percentile. */
    private static final double Z975 = 1.959963984540054;

    /** The statistics of {@code values}. */
    public static Statistics of(double[] values) {
        int n = values.length;
        if (n == 0) {
            return new Statistics(0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);
        }
        double sum = 0;
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (double v : values) {
            sum += v;
            min = Math.min(min, v);
            max = Math.max(max, v);
        }
        double mean = sum / n;
        if (n == 1) {
            return new Statistics(1, mean, Double.NaN, Double.NaN, min, max);
        }
        if (min == max) {
            // All alike: no spread, exactly. Summing them rounds, and the mean of 32 values of 1.7929 is
            // not 1.7929 in binary: the deviations from it made an sd of 2.4e-16 that looked like one.
            return new Statistics(n, min, 0.0, 0.0, min, max);
        }
        double squares = 0;
        for (double v : values) {
            squares += (v - mean) * (v - mean);
        }
        double sd = Math.sqrt(squares / (n - 1));
        return new Statistics(n, mean, sd, t975(n - 1) * sd / Math.sqrt(n), min, max);
    }

    /**
     * Student's t 97.5th percentile for {@code df} degrees of freedom: from the table up to 30, beyond
     * by the Cornish-Fisher expansion about the normal (within 1e-5 there).
     */
    static double t975(int df) {
        if (df < 1) {
            throw new IllegalArgumentException("degrees of freedom must be 1 or more, got " + df);
        }
        if (df <= T975.length) {
            return T975[df - 1];
        }
        double z = Z975;
        double z3 = z * z * z;
        double z5 = z3 * z * z;
        double z7 = z5 * z * z;
        return z + (z3 + z) / (4.0 * df) + (5 * z5 + 16 * z3 + 3 * z) / (96.0 * df * df)
                + (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384.0 * df * df * df);
    }
}
