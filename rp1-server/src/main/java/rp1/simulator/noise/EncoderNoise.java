package rp1.simulator.noise;

import java.util.HashMap;
import java.util.Map;

import rp1.rossum.event.RsEncoderStatusEvent;

/**
 * Missed encoder counts: each interval boundary a wheel's encoder crosses is missed with the settings'
 * probability. The wheel keeps the true counts; what it reports lacks the counts missed since its
 * accumulators were last cleared. The misses among the counts made since the previous report are
 * drawn when the encoder is reported.
 */
final class EncoderNoise {
    private final double miss;
    private final Draws draws;
    /** Per encoder (wheel part id): what the truth and the misses were at its last report. */
    private final Map<Integer, Counts> counts = new HashMap<>();

    EncoderNoise(NoiseSettings settings, long seed, int robot) {
        miss = settings.encoderMiss;
        draws = new Draws(seed, robot, Draws.Quantity.ENCODER);
    }

    /** The report the client gets for the true one. */
    RsEncoderStatusEvent report(RsEncoderStatusEvent truth) {
        Counts c = counts.computeIfAbsent(truth.encoderID, id -> new Counts());
        int made = Math.max(0, truth.absoluteAccumulatorValue - c.absolute);
        int signedMade = truth.accumulatorValue - c.signed;
        int missed = draws.binomial(made, miss);
        c.missedAbsolute += missed;
        c.missedSigned += Integer.signum(signedMade) * Math.min(missed, Math.abs(signedMade));
        RsEncoderStatusEvent seen = new RsEncoderStatusEvent(truth.simTime, truth.requestIndex, truth.encoderID,
                truth.accumulatorValue - c.missedSigned, truth.absoluteAccumulatorValue - c.missedAbsolute,
                truth.quadratureValue, truth.encoderInterval, truth.encoderAngle, truth.clearOnReport);
        if (truth.clearOnReport) {
            counts.remove(truth.encoderID);
        } else {
            c.signed = truth.accumulatorValue;
            c.absolute = truth.absoluteAccumulatorValue;
        }
        return seen;
    }

    private static final class Counts {
        int signed;
        int absolute;
        int missedSigned;
        int missedAbsolute;
    }
}
