package rp1.rossum;

import java.util.Locale;

/**
 * Inches, as RP1 defines them: 39.3696 inches per metre (12 of RP1's feet). Read-out like
 * {@code "  64-18/32 in"}.
 */
public class RsInches extends RsUnits {
    /** Inches per metre, the conversion the floor-plan language uses. */
    public static final double INCHES_PER_METER = 39.3696;

    /** Inches, without a resolution for rounding. */
    public RsInches() {
        super("inches");
        conversionFactor[0] = INCHES_PER_METER;
    }

    @Override
    public double userToInternal(double value) {
        return value / INCHES_PER_METER;
    }

    @Override
    public double internalToUser(double value) {
        return value * INCHES_PER_METER;
    }

    @Override
    protected String formatStandard(double internalValue) {
        int[] in = inchesAnd32nds(Math.abs(internalValue) * INCHES_PER_METER);
        String sign = internalValue < 0 ? "-" : "";
        return String.format(Locale.ROOT, "%s%4d-%02d/32 in", sign, in[0], in[1]);
    }
}
