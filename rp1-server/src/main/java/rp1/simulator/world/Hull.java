package rp1.simulator.world;

import java.util.Arrays;
import java.util.Comparator;

/**
 * The convex hull of one polygon of a robot's outlines, in body coordinates, counter-clockwise, with a
 * circle around it: the contact search projects it onto an axis to show two robots apart without
 * placing their outlines ({@link SeparatingAxes}). Each hull vertex is a vertex of the polygon, and
 * remembers which. Every robot of a design shares its hulls ({@link OutlineSources}).
 */
final class Hull {
    private final double[] x;
    private final double[] y;
    /** The outward unit normal of the edge from vertex k to vertex k + 1 (none with fewer than three vertices). */
    private final double[] normalX;
    private final double[] normalY;
    /** Hull vertex k is vertex {@code vertex[k]} of the polygon. */
    private final int[] vertex;
    /**
     * Whether every vertex of the polygon is a vertex of the hull, in the hull's order or the reverse:
     * the polygon is convex, and along it, as along the hull, the distance in any direction rises to
     * its greatest and falls.
     */
    private final boolean convex;
    /**
     * By octant of the plane's directions (see {@link #octant}), the vertex farthest along the octant's
     * middle direction: where a climb to the farthest vertex along a direction starts, a few vertices
     * from its end on any hull.
     */
    private final int[] starts = new int[8];
    /** The middle of the polygon's box, and the distance of its farthest vertex from there. */
    private final double centreX;
    private final double centreY;
    private final double radius;

    private Hull(double[] x, double[] y, int[] vertex, double centreX, double centreY, double radius, int count) {
        this.x = x;
        this.y = y;
        this.vertex = vertex;
        this.convex = inOrder(vertex, count);
        for (int o = 0; o < 8 && x.length > 0; o++) {
            double angle = (o + 0.5) * Math.PI / 4;
            starts[o] = farthest(Math.cos(angle), Math.sin(angle), 0);
        }
        this.centreX = centreX;
        this.centreY = centreY;
        this.radius = radius;
        int n = x.length;
        normalX = new double[n < 3 ? 0 : n];
        normalY = new double[n < 3 ? 0 : n];
        for (int k = 0; k < normalX.length; k++) {
            int k1 = k + 1 == n ? 0 : k + 1;
            double ex = x[k1] - x[k];
            double ey = y[k1] - y[k];
            double length = Math.hypot(ex, ey);
            normalX[k] = ey / length;
            normalY[k] = -ex / length;
        }
    }

    /** The hulls of each polygon of {@code outlines} (each x0, y0, x1, y1, ...). */
    static Hull[] of(double[][] outlines) {
        Hull[] hulls = new Hull[outlines.length];
        for (int i = 0; i < outlines.length; i++) {
            hulls[i] = of(outlines[i]);
        }
        return hulls;
    }

    /** The hull of {@code polygon} (x0, y0, x1, y1, ...): Andrew's monotone chain. */
    static Hull of(double[] polygon) {
        int count = polygon.length / 2;
        if (count == 0) {
            return new Hull(new double[0], new double[0], new int[0], 0.0, 0.0, 0.0, 0);
        }
        Integer[] points = new Integer[count];
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < count; k++) {
            points[k] = k;
            x0 = Math.min(x0, polygon[2 * k]);
            y0 = Math.min(y0, polygon[2 * k + 1]);
            x1 = Math.max(x1, polygon[2 * k]);
            y1 = Math.max(y1, polygon[2 * k + 1]);
        }
        double cx = 0.5 * (x0 + x1);
        double cy = 0.5 * (y0 + y1);
        double r = 0.0;
        for (int k = 0; k < count; k++) {
            r = Math.max(r, Math.hypot(polygon[2 * k] - cx, polygon[2 * k + 1] - cy));
        }
        Comparator<Integer> byX = Comparator.comparingDouble(k -> polygon[2 * k]);
        Arrays.sort(points, byX.thenComparingDouble(k -> polygon[2 * k + 1]));
        int[] hull = new int[2 * count + 1];
        int h = 0;
        // Lower chain left to right, then upper chain right to left; collinear points are dropped.
        for (int pass = 0; pass < 2; pass++) {
            int floor = h;
            for (int s = 0; s < count; s++) {
                int p = points[pass == 0 ? s : count - 1 - s];
                while (h >= floor + 2 && turn(polygon, hull[h - 2], hull[h - 1], p) <= 0.0) {
                    h--;
                }
                hull[h++] = p;
            }
            h--; // each chain's last point begins the other
        }
        if (h < 1) {
            h = Math.min(count, 1);
        }
        double[] x = new double[h];
        double[] y = new double[h];
        int[] vertex = Arrays.copyOf(hull, h);
        for (int k = 0; k < h; k++) {
            x[k] = polygon[2 * vertex[k]];
            y[k] = polygon[2 * vertex[k] + 1];
        }
        return new Hull(x, y, vertex, cx, cy, r, count);
    }

    /** Whether the hull's vertices are all {@code count} of the polygon's, in its order or the reverse. */
    private static boolean inOrder(int[] vertex, int count) {
        int n = vertex.length;
        if (n != count || n < 3) {
            return false;
        }
        int step = (vertex[1] - vertex[0] + n) % n;
        if (step != 1 && step != n - 1) {
            return false;
        }
        for (int k = 0; k < n; k++) {
            if ((vertex[(k + 1) % n] - vertex[k] + n) % n != step) {
                return false;
            }
        }
        return true;
    }

    /** Twice the signed area of the triangle of vertices p, q, r: positive for a left turn. */
    private static double turn(double[] polygon, int p, int q, int r) {
        double px = polygon[2 * p];
        double py = polygon[2 * p + 1];
        return (polygon[2 * q] - px) * (polygon[2 * r + 1] - py) - (polygon[2 * q + 1] - py) * (polygon[2 * r] - px);
    }

    /** Whether the polygon is convex, its vertices those of the hull in order (either way round). */
    boolean convex() {
        return convex;
    }

    double centreX() {
        return centreX;
    }

    double centreY() {
        return centreY;
    }

    /** Every vertex of the polygon lies within this of the centre. */
    double radius() {
        return radius;
    }

    int size() {
        return x.length;
    }

    /** Whether the hull has edges with normals (three vertices or more). */
    boolean hasEdges() {
        return normalX.length > 0;
    }

    double x(int k) {
        return x[k];
    }

    double y(int k) {
        return y[k];
    }

    double normalX(int k) {
        return normalX[k];
    }

    double normalY(int k) {
        return normalY[k];
    }

    int vertex(int k) {
        return vertex[k];
    }

    int next(int k) {
        return k + 1 == x.length ? 0 : k + 1;
    }

    int previous(int k) {
        return k == 0 ? x.length - 1 : k - 1;
    }

    /** How far vertex k lies along (dx, dy). */
    double along(int k, double dx, double dy) {
        return x[k] * dx + y[k] * dy;
    }

    /** How far the centre lies along (dx, dy). */
    double centreAlong(double dx, double dy) {
        return centreX * dx + centreY * dy;
    }

    /**
     * The vertex farthest along (dx, dy), climbing from the one farthest along the middle of its octant:
     * along a convex polygon the distance rises to its greatest and falls, so the climb ends there (up
     * to rounding, which the caller's margin covers), a few vertices on.
     */
    int farthest(double dx, double dy) {
        return x.length == 0 ? 0 : farthest(dx, dy, starts[octant(dx, dy)]);
    }

    /**
     * Which eighth of the plane's directions (dx, dy) points into, counter-clockwise from the x axis
     * (on a boundary, either side).
     */
    static int octant(double dx, double dy) {
        if (dy >= 0) {
            return dx >= 0 ? (dy < dx ? 0 : 1) : (dy > -dx ? 2 : 3);
        }
        return dx < 0 ? (-dy < -dx ? 4 : 5) : (-dy > dx ? 6 : 7);
    }

    /** The vertex farthest along (dx, dy), climbing from vertex {@code from} (see {@link #farthest(double, double)}). */
    int farthest(double dx, double dy, int from) {
        int n = x.length;
        if (n < 3) {
            return n == 2 && along(1, dx, dy) > along(0, dx, dy) ? 1 : 0;
        }
        int k = from < n ? from : 0;
        double best = along(k, dx, dy);
        int step = along(next(k), dx, dy) > best ? 1 : (along(previous(k), dx, dy) > best ? n - 1 : 0);
        for (int moves = 0; step != 0 && moves < n; moves++) {
            int j = (k + step) % n;
            double d = along(j, dx, dy);
            if (d <= best) {
                break;
            }
            k = j;
            best = d;
        }
        return k;
    }
}
