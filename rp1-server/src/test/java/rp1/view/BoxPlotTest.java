package rp1.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The box plots' axes and tick labels in a sweep's summary picture. */
class BoxPlotTest {
    @Test
    void anAxisOfValuesThatAreNeverNegativeStartsNoLowerThanZero() {
        // First collisions at 0.028 to 3.0 s: the axis went down to -0.12 s.
        assertArrayEquals(new double[] {0, 3.1486}, BoxPlot.range(0.028, 3.0), 1e-12);
        assertArrayEquals(new double[] {9.5, 20.5}, BoxPlot.range(10, 20), 1e-12, "padded where 0 is far");
        assertArrayEquals(new double[] {-1.1, 1.1}, BoxPlot.range(-1, 1), 1e-12, "a heading may be negative");
        assertArrayEquals(new double[] {0.45, 1.55}, BoxPlot.range(1, 1), 1e-12, "one value");
    }

    @Test
    void aWideTickLabelIsWrittenWithAPowerOfTen() {
        assertEquals("1.23e6", BoxPlot.compact(1234567.5));
        assertEquals("-1.23e-4", BoxPlot.compact(-0.000123456));
        assertEquals("1e6", BoxPlot.compact(999999));
        assertEquals("0", BoxPlot.compact(0));
    }
}
