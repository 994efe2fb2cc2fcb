package rp1.simulator.world;

import rp1.rossum.RsTransform;

/**
 * A robot's interactive shapes placed at one pose, as plain coordinate arrays with a bounding box per
 * polygon: what the robot-against-robot tests work on, many times per step in a crowd. Polygons are
 * closed implicitly (the last vertex joins the first). Touching counts as overlapping.
 */
final class Outlines {
    private final double[][] xs;
    private final double[][] ys;
    private final double[] minX;
    private final double[] minY;
    private final double[] maxX;
    private final double[] maxY;

    private Outlines(int n) {
        xs = new double[n][];
        ys = new double[n][];
        minX = new double[n];
        minY = new double[n];
        maxX = new double[n];
        maxY = new double[n];
    }

    /** {@code outlines} (each x0, y0, x1, y1, ... in body coordinates) placed at {@code pose}. */
    static Outlines at(double[][] outlines, RsTransform pose) {
        Outlines o = new Outlines(outlines.length);
        for (int i = 0; i < outlines.length; i++) {
            double[] xy = outlines[i];
            int n = xy.length / 2;
            double[] x = new double[n];
            double[] y = new double[n];
            double x0 = Double.POSITIVE_INFINITY;
            double y0 = Double.POSITIVE_INFINITY;
            double x1 = Double.NEGATIVE_INFINITY;
            double y1 = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < n; k++) {
                double bx = xy[2 * k];
                double by = xy[2 * k + 1];
                x[k] = pose.m11 * bx + pose.m12 * by + pose.m13;
                y[k] = pose.m21 * bx + pose.m22 * by + pose.m23;
                x0 = Math.min(x0, x[k]);
                y0 = Math.min(y0, y[k]);
                x1 = Math.max(x1, x[k]);
                y1 = Math.max(y1, y[k]);
            }
            o.xs[i] = x;
            o.ys[i] = y;
            o.minX[i] = x0;
            o.minY[i] = y0;
            o.maxX[i] = x1;
            o.maxY[i] = y1;
        }
        return o;
    }

    /** Whether any polygon of this overlaps or touches any polygon of {@code other}. */
    boolean overlaps(Outlines other) {
        for (int i = 0; i < xs.length; i++) {
            for (int j = 0; j < other.xs.length; j++) {
                if (boxGap(i, other, j) <= 0.0 && polygonsOverlap(i, other, j)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The distance between the nearest polygons of this and {@code other}, metres; 0 if they overlap. */
    double distance(Outlines other) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < xs.length; i++) {
            for (int j = 0; j < other.xs.length; j++) {
                if (boxGap(i, other, j) >= best) {
                    continue;
                }
                if (polygonsOverlap(i, other, j)) {
                    return 0.0;
                }
                best = Math.min(best, Math.sqrt(squaredDistance(xs[i], ys[i], other.xs[j], other.ys[j])));
            }
        }
        return best;
    }

    /** How far apart the boxes of polygon i of this and polygon j of {@code o} are (0 if they overlap). */
    private double boxGap(int i, Outlines o, int j) {
        double dx = Math.max(0.0, Math.max(minX[i] - o.maxX[j], o.minX[j] - maxX[i]));
        double dy = Math.max(0.0, Math.max(minY[i] - o.maxY[j], o.minY[j] - maxY[i]));
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** Whether polygon i of this and polygon j of {@code o} overlap or touch. */
    private boolean polygonsOverlap(int i, Outlines o, int j) {
        return edgesTouch(xs[i], ys[i], o.xs[j], o.ys[j])
                || (o.inBox(j, xs[i][0], ys[i][0]) && contains(o.xs[j], o.ys[j], xs[i][0], ys[i][0]))
                || (inBox(i, o.xs[j][0], o.ys[j][0]) && contains(xs[i], ys[i], o.xs[j][0], o.ys[j][0]));
    }

    private boolean inBox(int i, double x, double y) {
        return x >= minX[i] && x <= maxX[i] && y >= minY[i] && y <= maxY[i];
    }

    private static boolean edgesTouch(double[] ax, double[] ay, double[] bx, double[] by) {
        int na = ax.length;
        int nb = bx.length;
        for (int i = 0; i < na; i++) {
            int i1 = i + 1 == na ? 0 : i + 1;
            for (int j = 0; j < nb; j++) {
                int j1 = j + 1 == nb ? 0 : j + 1;
                if (segmentsTouch(ax[i], ay[i], ax[i1], ay[i1], bx[j], by[j], bx[j1], by[j1])) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether segments p and q share a point (end points included; collinear overlap counts). */
    private static boolean segmentsTouch(double px0, double py0, double px1, double py1,
                                         double qx0, double qy0, double qx1, double qy1) {
        if (Math.max(px0, px1) < Math.min(qx0, qx1) || Math.max(qx0, qx1) < Math.min(px0, px1)
                || Math.max(py0, py1) < Math.min(qy0, qy1) || Math.max(qy0, qy1) < Math.min(py0, py1)) {
            return false;
        }
        double d1 = cross(qx0, qy0, qx1, qy1, px0, py0);
        double d2 = cross(qx0, qy0, qx1, qy1, px1, py1);
        double d3 = cross(px0, py0, px1, py1, qx0, qy0);
        double d4 = cross(px0, py0, px1, py1, qx1, qy1);
        return d1 * d2 <= 0.0 && d3 * d4 <= 0.0;
    }

    private static double cross(double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    }

    /** Even-odd containment of (px, py) in the polygon; each edge ends where the next begins. */
    private static boolean contains(double[] x, double[] y, double px, double py) {
        int n = x.length;
        if (n < 3) {
            return false;
        }
        boolean inside = false;
        for (int i = 0, j = n - 1; i < n; j = i++) {
            if ((y[i] > py) != (y[j] > py) && px < x[j] + (py - y[j]) / (y[i] - y[j]) * (x[i] - x[j])) {
                inside = !inside;
            }
        }
        return inside;
    }

    /** The squared distance between two polygons that do not overlap: the nearest vertex to edge, either way. */
    private static double squaredDistance(double[] ax, double[] ay, double[] bx, double[] by) {
        return Math.min(verticesToEdges(ax, ay, bx, by), verticesToEdges(bx, by, ax, ay));
    }

    private static double verticesToEdges(double[] px, double[] py, double[] ex, double[] ey) {
        double best = Double.POSITIVE_INFINITY;
        int n = ex.length;
        for (int k = 0; k < px.length; k++) {
            for (int i = 0; i < n; i++) {
                int i1 = i + 1 == n ? 0 : i + 1;
                best = Math.min(best, squaredToSegment(px[k], py[k], ex[i], ey[i], ex[i1], ey[i1]));
            }
        }
        return best;
    }

    /** The squared distance from point (px, py) to the segment (x0, y0)-(x1, y1). */
    static double squaredToSegment(double px, double py, double x0, double y0, double x1, double y1) {
        double dx = x1 - x0;
        double dy = y1 - y0;
        double len2 = dx * dx + dy * dy;
        double u = len2 == 0.0 ? 0.0 : ((px - x0) * dx + (py - y0) * dy) / len2;
        u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
        double ex = px - (x0 + u * dx);
        double ey = py - (y0 + u * dy);
        return ex * ex + ey * ey;
    }
}
