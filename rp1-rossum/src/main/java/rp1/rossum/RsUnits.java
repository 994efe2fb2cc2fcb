package rp1.rossum;

import java.util.Locale;

/**
 * A system of user units (metres, feet, inches) for floor plans and coordinate read-outs. Internally
 * every length is in metres; a units object converts between the two and formats values for display.
 * {@code conversionFactor[0]} is the number of user units per metre.
 */
public abstract class RsUnits {
    /** {@code conversionFactor[0]}: user units per metre. */
    protected double[] conversionFactor;
    private final String name;
    private double userResolution;
    private double internalResolution;
    private String defaultFormat;

    /** Units called {@code name} (as written in a floor plan, e.g. "meters"). */
    public RsUnits(String name) {
        this.name = name;
        conversionFactor = new double[] {1.0};
    }

    /** Converts a value in these units to metres. */
    public abstract double userToInternal(double value);

    /** Converts metres to these units. */
    public abstract double internalToUser(double value);

    /** Rounds a value in user units to the nearest multiple of the user resolution (if one is set). */
    public double resolveUserCoordinate(double value) {
        return resolve(value, userResolution);
    }

    /**
     * Sets the step {@link #resolveUserCoordinate} rounds to; 0 (or less) for none.
     *
     * @param resolution the step in these units
     */
    public void setUserResolution(double resolution) {
        userResolution = Math.max(0.0, resolution);
    }

    /**
     * The step {@link #resolveUserCoordinate} rounds to.
     *
     * @return the step in these units, 0 for none
     */
    public double getUserResolution() {
        return userResolution;
    }

    /** Rounds a value in metres to the nearest multiple of the internal resolution (if one is set). */
    public double resolveInternalCoordinate(double value) {
        return resolve(value, internalResolution);
    }

    /**
     * Sets the step {@link #resolveInternalCoordinate} rounds to; 0 (or less) for none.
     *
     * @param resolution the step in metres
     */
    public void setInternalResolution(double resolution) {
        internalResolution = Math.max(0.0, resolution);
    }

    /**
     * The step {@link #resolveInternalCoordinate} rounds to.
     *
     * @return the step in metres, 0 for none
     */
    public double getInternalResolution() {
        return internalResolution;
    }

    private static double resolve(double value, double resolution) {
        return resolution > 0.0 ? Math.round(value / resolution) * resolution : value;
    }

    /**
     * Sets a {@link String#format} pattern taking one double (the value in user units) that
     * {@link #format(double)} uses instead of these units' standard read-out; null restores it.
     */
    public void setDefaultFormat(String format) {
        defaultFormat = format;
    }

    /** Formats a length given in metres for display in these units. */
    public String format(double internalValue) {
        if (defaultFormat != null) {
            return format(defaultFormat, internalValue);
        }
        return formatStandard(internalValue);
    }

    /** Formats a length given in metres with a {@link String#format} pattern taking the user value. */
    public String format(String format, double internalValue) {
        return String.format(Locale.ROOT, format, internalToUser(internalValue));
    }

    /** The standard read-out of these units for a length in metres. */
    protected abstract String formatStandard(double internalValue);

    /** The name, as written in a floor plan ("meters", "feet", "inches"). */
    public String getName() {
        return name;
    }

    /**
     * Whole inches and 32nds of an inch for a non-negative number of inches; the 32nds are rounded
     * but never reach 32 (a value that would round up shows 31/32).
     */
    static int[] inchesAnd32nds(double inches) {
        int whole = (int) Math.floor(inches);
        int n32 = (int) Math.round((inches - whole) * 32.0);
        return new int[] {whole, Math.min(n32, 31)};
    }

    @Override
    public String toString() {
        return name;
    }
}
