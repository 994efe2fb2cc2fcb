package rp1.simulator.noise;

/**
 * How noisy a run's sensors and motion are (docs/properties.md, the {@code noise...} keys). Every
 * figure 0 is RP1 0.60's perfect world, and nothing is drawn at all. Immutable.
 */
public final class NoiseSettings {
    /** No noise: the default. */
    public static final NoiseSettings OFF = new NoiseSettings(0, 0, 0, 0, 0, 0, 0);

    /** Standard deviation of a range sensor's reported range, metres. */
    public final double rangeSigma;
    /** Probability that a range sensor's reading is lost (reported as detecting nothing). */
    public final double rangeDropout;
    /** Standard deviation of a target sensor's reported range, metres. */
    public final double targetRangeSigma;
    /** Standard deviation of a target sensor's reported bearing, radians. */
    public final double targetBearingSigma;
    /** Probability that an encoder misses each interval boundary it crosses. */
    public final double encoderMiss;
    /** Standard deviation of the distance a motion covers, as a fraction of the commanded distance. */
    public final double slipDistanceSigma;
    /** Standard deviation of the turn a motion makes, as a fraction of the commanded turn. */
    public final double slipTurnSigma;

    /**
     * Settings with these figures; each must be finite and not negative, and the two probabilities
     * at most 1.
     */
    public NoiseSettings(double rangeSigma, double rangeDropout, double targetRangeSigma, double targetBearingSigma,
                         double encoderMiss, double slipDistanceSigma, double slipTurnSigma) {
        this.rangeSigma = check("rangeSigma", rangeSigma, Double.MAX_VALUE);
        this.rangeDropout = check("rangeDropout", rangeDropout, 1.0);
        this.targetRangeSigma = check("targetRangeSigma", targetRangeSigma, Double.MAX_VALUE);
        this.targetBearingSigma = check("targetBearingSigma", targetBearingSigma, Double.MAX_VALUE);
        this.encoderMiss = check("encoderMiss", encoderMiss, 1.0);
        this.slipDistanceSigma = check("slipDistanceSigma", slipDistanceSigma, Double.MAX_VALUE);
        this.slipTurnSigma = check("slipTurnSigma", slipTurnSigma, Double.MAX_VALUE);
    }

    private static double check(String name, double value, double max) {
        if (!(value >= 0.0 && value <= max)) {
            throw new IllegalArgumentException(name + " must be in [0, " + max + "], got " + value);
        }
        return value;
    }

    /** Whether range or target sensors are noisy. */
    boolean sensorsNoisy() {
        return rangeSigma > 0 || rangeDropout > 0 || targetRangeSigma > 0 || targetBearingSigma > 0;
    }

    /** Whether motions slip. */
    boolean motionNoisy() {
        return slipDistanceSigma > 0 || slipTurnSigma > 0;
    }

    /** Whether every figure is 0: RP1 0.60's behaviour. */
    public boolean isOff() {
        return !sensorsNoisy() && encoderMiss == 0 && !motionNoisy();
    }

    @Override
    public String toString() {
        return "NoiseSettings[range " + rangeSigma + " m, dropout " + rangeDropout + ", target range "
                + targetRangeSigma + " m, bearing " + targetBearingSigma + " rad, encoder miss " + encoderMiss
                + ", slip " + slipDistanceSigma + " of distance, " + slipTurnSigma + " of turn]";
    }
}
