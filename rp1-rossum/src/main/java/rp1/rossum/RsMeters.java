package rp1.rossum;

import java.util.Locale;

/** Metres, the internal unit; read-out like {@code "   1.234 m"}. */
public class RsMeters extends RsUnits {
    /** Metres, without a resolution for rounding. */
    public RsMeters() {
        super("meters");
    }

    @Override
    public double userToInternal(double value) {
        return value;
    }

    @Override
    public double internalToUser(double value) {
        return value;
    }

    @Override
    protected String formatStandard(double internalValue) {
        return String.format(Locale.ROOT, "%8.3f m", internalValue);
    }
}
