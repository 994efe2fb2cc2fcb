package rp1.rossum;

import java.util.Locale;

/**
 * Kilometres: 1000 metres. The original's floor-plan language rejects {@code kilometers} although
 * its User's Guide documents it; this implementation accepts it. Read-out like {@code "  0.012345 km"}.
 */
public class RsKilometers extends RsUnits {
    /** Metres per kilometre. */
    public static final double METERS_PER_KILOMETER = 1000.0;

    /** Kilometres, without a resolution for rounding. */
    public RsKilometers() {
        super("kilometers");
        conversionFactor[0] = 1.0 / METERS_PER_KILOMETER;
    }

    @Override
    public double userToInternal(double value) {
        return value * METERS_PER_KILOMETER;
    }

    @Override
    public double internalToUser(double value) {
        return value / METERS_PER_KILOMETER;
    }

    @Override
    protected String formatStandard(double internalValue) {
        return String.format(Locale.ROOT, "%10.6f km", internalValue / METERS_PER_KILOMETER);
    }
}
