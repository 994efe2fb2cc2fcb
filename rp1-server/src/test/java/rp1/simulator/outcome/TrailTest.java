package rp1.simulator.outcome;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import java.util.stream.IntStream;

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

    /**
     * The points kept are those a plain Douglas-Peucker keeps measuring every distance with
     * {@link Math#hypot}: on robot-like wandering paths, on paths with points exactly as far as each
     * other and as the tolerance, and on a path doubling back on itself.
     */
    @Test
    void theSamePointsAreKeptAsWithHypotEverywhere() {
        SplittableRandom random = new SplittableRandom(21);
        for (int trial = 0; trial < 3000; trial++) {
            int n = 2 + random.nextInt(200);
            double[] xy = new double[2 * n];
            double x = random.nextDouble(-5, 5);
            double y = random.nextDouble(-5, 5);
            double heading = random.nextDouble(2 * Math.PI);
            for (int i = 0; i < n; i++) {
                xy[2 * i] = x;
                xy[2 * i + 1] = y;
                if (trial % 3 == 0) {
                    // Whole multiples of the tolerance: ties between points and with the tolerance.
                    x += 0.002 * random.nextInt(-3, 4);
                    y += 0.002 * random.nextInt(-3, 4);
                } else {
                    heading += random.nextInt(10) == 0 ? random.nextDouble(-3, 3) : random.nextDouble(-0.01, 0.01);
                    x += 0.01 * Math.cos(heading);
                    y += 0.01 * Math.sin(heading);
                }
            }
            double tolerance = trial % 3 == 0 ? 0.002 * random.nextInt(1, 3) : 0.002;
            assertArrayEquals(everyDistanceByHypot(xy, tolerance), Trail.simplified(xy, tolerance), "trial " + trial);
        }
        double[] back = {0, 0, 1, 0, 2, 0, 1, 0, 0, 0, 1, 0};
        assertArrayEquals(everyDistanceByHypot(back, 0.002), Trail.simplified(back, 0.002));
        for (int trial = 0; trial < 300; trial++) {
            // Out along a bent way and back over the very same points, as a bumper backs off.
            int n = 3 + random.nextInt(60);
            double[] out = new double[4 * n];
            double heading = random.nextDouble(2 * Math.PI);
            for (int i = 1; i < n; i++) {
                heading += random.nextDouble(-0.3, 0.3);
                out[2 * i] = out[2 * i - 2] + 0.01 * Math.cos(heading);
                out[2 * i + 1] = out[2 * i - 1] + 0.01 * Math.sin(heading);
            }
            for (int i = 0; i < n; i++) {
                out[2 * (n + i)] = out[2 * (n - 1 - i)];
                out[2 * (n + i) + 1] = out[2 * (n - 1 - i) + 1];
            }
            assertArrayEquals(everyDistanceByHypot(out, 0.002), Trail.simplified(out, 0.002), "retraced " + trial);
        }
    }

    @Test
    void shorterAnswersAsHypotDoes() {
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 200_000; i++) {
            double dx = random.nextDouble(-0.05, 0.05);
            double dy = random.nextDouble(-0.05, 0.05);
            // Half the limits are the distance itself, or a neighbouring double: the rounding band.
            double exact = Math.hypot(dx, dy);
            double limit = i % 2 == 0 ? random.nextDouble(0.05)
                    : i % 3 == 0 ? exact : i % 3 == 1 ? Math.nextUp(exact) : Math.nextDown(exact);
            assertEquals(exact < limit, Trail.shorter(dx, dy, limit), dx + ", " + dy + " against " + limit);
        }
    }

    /** Douglas and Peucker as written down, recursively, every distance by {@link Math#hypot}. */
    private static double[] everyDistanceByHypot(double[] xy, double tolerance) {
        int n = xy.length / 2;
        boolean[] keep = new boolean[n];
        keep[0] = keep[n - 1] = true;
        keepFarthest(xy, 0, n - 1, tolerance, keep);
        return IntStream.range(0, n).filter(i -> keep[i]).flatMap(i -> IntStream.of(2 * i, 2 * i + 1))
                .mapToDouble(i -> xy[i]).toArray();
    }

    private static void keepFarthest(double[] xy, int a, int b, double tolerance, boolean[] keep) {
        int farthest = -1;
        double most = tolerance;
        for (int i = a + 1; i < b; i++) {
            double dx = xy[2 * b] - xy[2 * a];
            double dy = xy[2 * b + 1] - xy[2 * a + 1];
            double px = xy[2 * i] - xy[2 * a];
            double py = xy[2 * i + 1] - xy[2 * a + 1];
            double length2 = dx * dx + dy * dy;
            double t = length2 == 0 ? 0 : Math.max(0, Math.min(1, (px * dx + py * dy) / length2));
            double d = Math.hypot(px - t * dx, py - t * dy);
            if (d > most) {
                most = d;
                farthest = i;
            }
        }
        if (farthest >= 0) {
            keep[farthest] = true;
            keepFarthest(xy, a, farthest, tolerance, keep);
            keepFarthest(xy, farthest, b, tolerance, keep);
        }
    }
}
