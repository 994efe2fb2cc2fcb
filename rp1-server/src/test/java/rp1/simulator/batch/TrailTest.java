package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

/** Trails keep the points that shape them and leave out the others. */
class TrailTest {
    @Test
    void pointsOnAStraightRunAreLeftOutAndCornersKept() {
        double[] path = {0, 0, 0.01, 0, 0.02, 0.001, 0.03, 0, 0.04, 0, 0.04, 0.01, 0.04, 0.02};
        assertArrayEquals(new double[] {0, 0, 0.04, 0, 0.04, 0.02}, Trail.simplified(path, 0.002));
        assertArrayEquals(new double[] {0, 0, 0.02, 0.001, 0.04, 0, 0.04, 0.02},
                Trail.simplified(path, 0.0005), "a bump larger than the tolerance stays");
        assertArrayEquals(new double[] {1, 2, 3, 4}, Trail.simplified(new double[] {1, 2, 3, 4}, 0.1));
    }
}
