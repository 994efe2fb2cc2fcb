package rp1.simulator.batch;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * Numbers as a sweep's tables write them: rounded to what the model resolves (docs/guide.md lists
 * the places per unit), a robot's own results as it reported them, without trailing zeros, empty for
 * "none" (NaN).
 */
final class Numbers {
    /** Places of metres, radians and simulated seconds: 0.1 mm, 0.1 mrad, 0.1 ms. */
    static final int MODEL = 4;
    /** Places of wall-clock seconds. */
    static final int WALL = 3;
    /** Places of statistics, at least: more where a value is small, to keep 6 significant digits. */
    static final int FREE = 6;

    private Numbers() {
    }

    /** {@code v} rounded to {@code places} decimals, trailing zeros dropped; empty if NaN. */
    static String format(double v, int places) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        BigDecimal d = BigDecimal.valueOf(v).setScale(places, RoundingMode.HALF_EVEN).stripTrailingZeros();
        return d.signum() == 0 ? "0" : d.toPlainString();
    }

    /**
     * A statistic: {@link #FREE} places, or as many more as keep 6 significant digits of a value
     * smaller than 0.1 (a robot's results may be of any size: 1e-7 is not 0).
     */
    static String statistic(double v) {
        if (v == 0.0 || Double.isNaN(v) || Double.isInfinite(v) || Math.abs(v) >= 0.1) {
            return format(v, FREE);
        }
        int leadingZeros = -(int) Math.floor(Math.log10(Math.abs(v))) - 1;
        return format(v, Math.max(FREE, leadingZeros + FREE));
    }

    /**
     * A robot's own result as it reported it: the shortest decimal that reads back as the same double
     * (the model's resolution says nothing of what a robot measures).
     */
    static String asReported(double v) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        BigDecimal d = BigDecimal.valueOf(v).stripTrailingZeros();
        return d.signum() == 0 ? "0" : d.toPlainString();
    }

    /** A field of a table as a number: NaN if empty or not a number. */
    static double parse(String s) {
        if (s == null || s.isEmpty()) {
            return Double.NaN;
        }
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
