package rp1.web;

/**
 * The quanta of the page's encoding (docs/recording.md, "The replay page") and the writing of the
 * comma-separated integer lists it is made of.
 */
final class Encoding {
    /** Positions and lengths are written in units of a tenth of a millimetre. */
    static final double METRES = 1e-4;
    /** Headings and steering angles are written in units of a ten-thousandth of a radian. */
    static final double RADIANS = 1e-4;

    private Encoding() {
    }

    /** A length in the encoding's units. */
    static long metres(double v) {
        return Math.round(v / METRES);
    }

    /** An angle in the encoding's units. */
    static long radians(double v) {
        return Math.round(v / RADIANS);
    }

    /** Appends the numbers to a comma-separated list. */
    static void append(StringBuilder list, long... values) {
        for (long v : values) {
            if (list.length() > 0) {
                list.append(',');
            }
            list.append(v);
        }
    }
}
