package rp1.simulator.outcome;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;

/**
 * Where one robot went in a run: pieces of path in world metres, each {@code x0, y0, x1, y1, ...}; a
 * new piece begins wherever the robot was placed anew.
 */
public record Trail(String robot, List<double[]> pieces) {
    /**
     * Factors on a squared distance beyond which the distances surely compare as their squares do:
     * squaring and summing round by about 1e-16, {@code hypot} by less than that.
     */
    private static final double SURELY_LESS = 1.0 - 1.0e-9;
    private static final double SURELY_MORE = 1.0 + 1.0e-9;

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
            int farthest = farthest(xy, span[0], span[1], tolerance);
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
     * The point between {@code a} and {@code b} farthest from the segment joining them, the first of
     * equals, if it is farther than {@code tolerance} ({@link Math#hypot} measuring); -1 if none is.
     * Squared distances decide wherever they surely agree with {@code hypot} (a relative margin far
     * above their rounding), and {@code hypot}, exact but slow, only where two distances are within
     * it: the same point comes out as if every distance were measured with {@code hypot}.
     */
    private static int farthest(double[] xy, int a, int b, double tolerance) {
        double ax = xy[2 * a];
        double ay = xy[2 * a + 1];
        double dx = xy[2 * b] - ax;
        double dy = xy[2 * b + 1] - ay;
        double length2 = dx * dx + dy * dy;
        int farthest = -1;
        double mostSquared = tolerance * tolerance;
        double mostX = Double.NaN;
        double mostY = Double.NaN;
        // hypot of the farthest so far: the tolerance while there is none, NaN until it is needed
        // after a point was taken on its square alone. A robot backing out along its way in leaves
        // points exactly as far from the chord as others: equal offsets are passed over unmeasured.
        double most = tolerance;
        for (int i = a + 1; i < b; i++) {
            double px = xy[2 * i] - ax;
            double py = xy[2 * i + 1] - ay;
            double t = length2 == 0 ? 0 : Math.max(0, Math.min(1, (px * dx + py * dy) / length2));
            double ex = px - t * dx;
            double ey = py - t * dy;
            double squared = ex * ex + ey * ey;
            if (squared < mostSquared * SURELY_LESS) {
                continue;
            }
            double exact = Double.NaN;
            if (squared <= mostSquared * SURELY_MORE) {
                if (Math.abs(ex) == Math.abs(mostX) && Math.abs(ey) == Math.abs(mostY)) {
                    continue;
                }
                if (Double.isNaN(most)) {
                    most = Math.hypot(mostX, mostY);
                }
                exact = Math.hypot(ex, ey);
                if (!(exact > most)) {
                    continue;
                }
            }
            farthest = i;
            mostSquared = squared;
            mostX = ex;
            mostY = ey;
            most = exact;
        }
        return farthest;
    }

    /**
     * Whether {@code Math.hypot(dx, dy) < distance}, computed from squares unless the two are within
     * rounding of each other.
     */
    static boolean shorter(double dx, double dy, double distance) {
        double squared = dx * dx + dy * dy;
        double limit = distance * distance;
        if (squared < limit * SURELY_LESS) {
            return true;
        }
        if (squared > limit * SURELY_MORE) {
            return false;
        }
        return Math.hypot(dx, dy) < distance;
    }

    /** A piece of path from its coordinates {@code x0, y0, x1, y1, ...}. */
    public static double[] piece(List<Double> xy) {
        double[] out = new double[xy.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = xy.get(i);
        }
        return out;
    }
}
