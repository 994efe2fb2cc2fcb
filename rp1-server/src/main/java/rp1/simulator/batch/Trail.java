package rp1.simulator.batch;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;

/**
 * Where one robot went in a run: pieces of path in world metres, each {@code x0, y0, x1, y1, ...}; a
 * new piece begins wherever the robot was placed anew.
 */
public record Trail(String robot, List<double[]> pieces) {
    /** Copies the list (the arrays are not changed once a trail is made). */
    public Trail {
        pieces = List.copyOf(pieces);
    }

    /**
     * {@code xy} ({@code x0, y0, x1, y1, ...}) without the points that lie within {@code tolerance} of
     * the line through the points kept on either side (Douglas and Peucker): a robot that drives
     * straight for a metre leaves two points instead of a hundred, and the picture is the same.
     */
    static double[] simplified(double[] xy, double tolerance) {
        int n = xy.length / 2;
        if (n < 3) {
            return xy;
        }
        boolean[] keep = new boolean[n];
        keep[0] = true;
        keep[n - 1] = true;
        Deque<int[]> spans = new ArrayDeque<>();
        spans.push(new int[] {0, n - 1});
        while (!spans.isEmpty()) {
            int[] span = spans.pop();
            int farthest = -1;
            double most = tolerance;
            double surelyLess = below(most);
            for (int i = span[0] + 1; i < span[1]; i++) {
                double d = distance(xy, i, span[0], span[1], surelyLess);
                if (d > most) {
                    most = d;
                    surelyLess = below(most);
                    farthest = i;
                }
            }
            if (farthest >= 0) {
                keep[farthest] = true;
                spans.push(new int[] {span[0], farthest});
                spans.push(new int[] {farthest, span[1]});
            }
        }
        int kept = 0;
        for (boolean k : keep) {
            kept += k ? 1 : 0;
        }
        double[] out = new double[2 * kept];
        for (int i = 0, j = 0; i < n; i++) {
            if (keep[i]) {
                out[j++] = xy[2 * i];
                out[j++] = xy[2 * i + 1];
            }
        }
        return out;
    }

    /**
     * A squared distance under which the distance itself is surely below {@code d}, rounding
     * included: most points lie well within the tolerance, and for them the exact (and slow)
     * {@link Math#hypot} is not needed to know it.
     */
    private static double below(double d) {
        return d * d * (1.0 - 1.0e-9);
    }

    /**
     * How far point {@code i} is from the segment between points {@code a} and {@code b}; 0 if its
     * squared distance is below {@code surelyLess}.
     */
    private static double distance(double[] xy, int i, int a, int b, double surelyLess) {
        double ax = xy[2 * a];
        double ay = xy[2 * a + 1];
        double dx = xy[2 * b] - ax;
        double dy = xy[2 * b + 1] - ay;
        double px = xy[2 * i] - ax;
        double py = xy[2 * i + 1] - ay;
        double length2 = dx * dx + dy * dy;
        double t = length2 == 0 ? 0 : Math.max(0, Math.min(1, (px * dx + py * dy) / length2));
        double ex = px - t * dx;
        double ey = py - t * dy;
        return ex * ex + ey * ey < surelyLess ? 0.0 : Math.hypot(ex, ey);
    }

    /** A piece of path from its coordinates {@code x0, y0, x1, y1, ...}. */
    static double[] piece(List<Double> xy) {
        double[] out = new double[xy.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = xy.get(i);
        }
        return out;
    }
}
