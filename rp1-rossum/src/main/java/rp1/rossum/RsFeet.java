package rp1.rossum;

import java.util.Locale;

/**
 * Feet, as RP1 defines them: 3.2808 feet per metre (so one foot is 0.3048037 m, not exactly 0.3048).
 * Read-out like {@code "  5 ft  4-18/32 in"}.
 */
public class RsFeet extends RsUnits {
    /** Feet per metre, the conversion the floor-plan language uses. */
    public static final double FEET_PER_METER = 3.2808;

    /** Feet, without a resolution for rounding. */
    public RsFeet() {
        super("feet");
        conversionFactor[0] = FEET_PER_METER;
    }

    @Override
    public double userToInternal(double value) {
        return value / FEET_PER_METER;
    }

    @Override
    public double internalToUser(double value) {
        return value * FEET_PER_METER;
    }

    @Override
    protected String formatStandard(double internalValue) {
        double inches = Math.abs(internalValue) * RsInches.INCHES_PER_METER;
        int feet = (int) Math.floor(inches / 12.0);
        int[] in = inchesAnd32nds(inches - 12.0 * feet);
        String sign = internalValue < 0 ? "-" : "";
        return String.format(Locale.ROOT, "%s%3d ft %2d-%02d/32 in", sign, feet, in[0], in[1]);
    }
}
