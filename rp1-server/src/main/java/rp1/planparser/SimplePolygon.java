package rp1.planparser;

import java.util.Arrays;
import java.util.Comparator;

/**
 * Tests that a polygon is simple, as the User's Guide requires of obstacles and paint: no vertex is
 * repeated, edges that follow each other do not fold back onto each other, and edges that do not
 * follow each other have no point in common. (The original did not check; a self-intersecting
 * polygon gave meaningless inside/outside answers for paint sensors and collisions.)
 *
 * <p>Edges are swept in order of their left ends, so only edges whose x-ranges overlap are compared;
 * the cost is near n log n for ordinary outlines.
 */
final class SimplePolygon {
    private SimplePolygon() {
    }

    /** The vertices x0, y0, ... without the last one if it repeats the first (the polygon closes anyway). */
    static double[] dropClosingVertex(double[] xy) {
        int n = xy.length;
        if (n >= 4 && xy[0] == xy[n - 2] && xy[1] == xy[n - 1]) {
            return Arrays.copyOf(xy, n - 2);
        }
        return xy;
    }

    /**
     * Why the closed polygon through vertices x0, y0, x1, y1, ... is not simple, or null if it is.
     * Vertices are numbered from 1 in the message.
     */
    static String findViolation(double[] xy) {
        int n = xy.length / 2;
        if (n < 3) {
            return "it has only " + n + " distinct vertices";
        }
        String folded = findFold(xy, n);
        return folded != null ? folded : findCrossing(xy, n);
    }

    /** Adjacent edges a-b, b-c overlap when a, b, c are collinear and c lies back towards a. */
    private static String findFold(double[] xy, int n) {
        for (int b = 0; b < n; b++) {
            int a = (b + n - 1) % n;
            int c = (b + 1) % n;
            if (same(xy, a, b)) {
                return "vertex " + (b + 1) + " repeats vertex " + (a + 1);
            }
            double abx = xy[2 * a] - xy[2 * b];
            double aby = xy[2 * a + 1] - xy[2 * b + 1];
            double cbx = xy[2 * c] - xy[2 * b];
            double cby = xy[2 * c + 1] - xy[2 * b + 1];
            if (abx * cby - aby * cbx == 0.0 && abx * cbx + aby * cby > 0.0) {
                return "the edges meeting at vertex " + (b + 1) + " lie on top of each other";
            }
        }
        return null;
    }

    private static String findCrossing(double[] xy, int n) {
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, Comparator.comparingDouble(i -> minX(xy, i, n)));
        for (int p = 0; p < n; p++) {
            int e = order[p];
            double right = maxX(xy, e, n);
            for (int q = p + 1; q < n && minX(xy, order[q], n) <= right; q++) {
                int f = order[q];
                if (!adjacent(e, f, n) && intersect(xy, e, f, n)) {
                    int first = Math.min(e, f);
                    int second = Math.max(e, f);
                    return "the edge from vertex " + edge(first, n) + " touches or crosses the edge from vertex "
                            + edge(second, n);
                }
            }
        }
        return null;
    }

    private static boolean adjacent(int e, int f, int n) {
        return Math.abs(e - f) == 1 || Math.abs(e - f) == n - 1;
    }

    /** Whether edges e and f (edge i runs from vertex i to vertex i+1) have a point in common. */
    private static boolean intersect(double[] xy, int e, int f, int n) {
        int e1 = (e + 1) % n;
        int f1 = (f + 1) % n;
        int d1 = orientation(xy, f, f1, e);
        int d2 = orientation(xy, f, f1, e1);
        int d3 = orientation(xy, e, e1, f);
        int d4 = orientation(xy, e, e1, f1);
        if (d1 * d2 < 0 && d3 * d4 < 0) {
            return true;
        }
        return (d1 == 0 && within(xy, f, f1, e)) || (d2 == 0 && within(xy, f, f1, e1))
                || (d3 == 0 && within(xy, e, e1, f)) || (d4 == 0 && within(xy, e, e1, f1));
    }

    /** The sign of the turn a, b, c: 1 anticlockwise, -1 clockwise, 0 collinear. */
    private static int orientation(double[] xy, int a, int b, int c) {
        double cross = (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1])
                - (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
        return cross > 0.0 ? 1 : cross < 0.0 ? -1 : 0;
    }

    /** Whether vertex c, collinear with a and b, lies within their bounding box (so on segment a-b). */
    private static boolean within(double[] xy, int a, int b, int c) {
        double x = xy[2 * c];
        double y = xy[2 * c + 1];
        return x >= Math.min(xy[2 * a], xy[2 * b]) && x <= Math.max(xy[2 * a], xy[2 * b])
                && y >= Math.min(xy[2 * a + 1], xy[2 * b + 1]) && y <= Math.max(xy[2 * a + 1], xy[2 * b + 1]);
    }

    private static double minX(double[] xy, int e, int n) {
        return Math.min(xy[2 * e], xy[2 * ((e + 1) % n)]);
    }

    private static double maxX(double[] xy, int e, int n) {
        return Math.max(xy[2 * e], xy[2 * ((e + 1) % n)]);
    }

    private static boolean same(double[] xy, int a, int b) {
        return xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1];
    }

    private static String edge(int e, int n) {
        return (e + 1) + " to vertex " + ((e + 1) % n + 1);
    }
}
