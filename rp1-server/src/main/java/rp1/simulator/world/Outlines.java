package rp1.simulator.world;

import rp1.rossum.RsTransform;

/**
 * A robot's interactive shapes placed at one pose, as plain coordinate arrays with a bounding box per
 * polygon: what the robot-against-robot tests work on, many times per step in a crowd. Polygons are
 * closed implicitly (the last vertex joins the first). Touching counts as overlapping. One is placed
 * anew at each pose asked for ({@link #place}), so that a sample allocates nothing; the contact search
 * keeps them ({@link PlacedOutlines}).
 */
final class Outlines {
    /** What this places: each polygon's x0, y0, x1, y1, ... in body coordinates. */
    private final double[][] source;
    private final double[][] xs;
    private final double[][] ys;
    private final double[] minX;
    private final double[] minY;
    private final double[] maxX;
    private final double[] maxY;
    /**
     * Per polygon: how far its farthest vertex is from the middle of its box (a bound for pruning), NaN
     * until a distance needs it (most outlines are only tested for overlap).
     */
    private final double[] radius;
    /** The edges of one polygon that {@link #edgesTouch} keeps, by index; long enough for any polygon of this. */
    private final int[] near;

    /** Room for {@code outlines} (each x0, y0, x1, y1, ... in body coordinates), not yet placed. */
    private Outlines(double[][] outlines) {
        source = outlines;
        int n = outlines.length;
        xs = new double[n][];
        ys = new double[n][];
        minX = new double[n];
        minY = new double[n];
        maxX = new double[n];
        maxY = new double[n];
        radius = new double[n];
        int most = 0;
        for (int i = 0; i < n; i++) {
            xs[i] = new double[outlines[i].length / 2];
            ys[i] = new double[outlines[i].length / 2];
            most = Math.max(most, xs[i].length);
        }
        near = new int[most];
    }

    /** {@code outlines} (each x0, y0, x1, y1, ... in body coordinates) placed at {@code pose}. */
    static Outlines at(double[][] outlines, RsTransform pose) {
        return new Outlines(outlines).place(pose);
    }

    /** Room to place {@code outlines} (each x0, y0, x1, y1, ... in body coordinates) in; not placed yet. */
    static Outlines roomFor(double[][] outlines) {
        return new Outlines(outlines);
    }

    /** What this places: each polygon's x0, y0, x1, y1, ... in body coordinates. */
    double[][] source() {
        return source;
    }

    /** Places these outlines anew at {@code pose}. Returns this, which no longer answers for the pose it had. */
    Outlines place(RsTransform pose) {
        for (int i = 0; i < source.length; i++) {
            double[] xy = source[i];
            int n = xy.length / 2;
            double[] x = xs[i];
            double[] y = ys[i];
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
            minX[i] = x0;
            minY[i] = y0;
            maxX[i] = x1;
            maxY[i] = y1;
            radius[i] = Double.NaN;
        }
        return this;
    }

    /** Whether any polygon of this overlaps or touches any polygon of {@code other}. */
    boolean overlaps(Outlines other) {
        for (int i = 0; i < xs.length; i++) {
            for (int j = 0; j < other.xs.length; j++) {
                if (boxGapSquared(i, other, j) <= 0.0 && polygonsOverlap(i, other, j)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The distance between the nearest polygons of this and {@code other}, metres; 0 if they overlap. */
    double distance(Outlines other) {
        return distance(other, Double.POSITIVE_INFINITY);
    }

    /**
     * The distance between the nearest polygons of this and {@code other} if it is at most {@code limit}
     * (bit for bit what {@link #distance(Outlines)} gives), else a value above {@code limit}: polygons
     * and vertex-edge pairs that cannot come within the limit are not looked at, which is most of them
     * when the question is only whether two robots touch.
     */
    double distance(Outlines other, double limit) {
        double beyond = limit + Nearest.SLACK;
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < xs.length; i++) {
            for (int j = 0; j < other.xs.length; j++) {
                double boxes = boxGap(i, other, j);
                if (boxes >= best || boxes > beyond) {
                    continue;
                }
                if (polygonsOverlap(i, other, j)) {
                    return 0.0;
                }
                best = Math.min(best, Math.sqrt(squaredDistance(i, other, j, Math.min(best, limit))));
            }
        }
        return best;
    }

    /**
     * Whether this and {@code other} overlap, come within {@code limit} of each other, or neither: 0 if
     * they overlap, {@code limit} if they do not but some polygons of the two are within {@code limit},
     * else a value above {@code limit}. It answers as {@link #distance(Outlines, double)} would be read
     * against 0 and {@code limit}, for less: the search for a vertex within reach of an edge ends at the
     * first one found, where the distance needs them all. (The two could differ only for outlines that
     * do not overlap and yet have a vertex on an edge to the last bit, at a distance of exactly 0.)
     */
    double within(Outlines other, double limit) {
        double beyond = limit + Nearest.SLACK;
        boolean near = false;
        for (int i = 0; i < xs.length; i++) {
            for (int j = 0; j < other.xs.length; j++) {
                if (boxGap(i, other, j) > beyond) {
                    continue;
                }
                if (polygonsOverlap(i, other, j)) {
                    return 0.0;
                }
                if (!near) {
                    Nearest n = new Nearest(limit, true);
                    n.verticesToEdges(xs[i], ys[i], other.xs[j], other.ys[j], other.minX[j], other.minY[j],
                            other.maxX[j], other.maxY[j], other.radius(j));
                    if (!n.found) {
                        n.verticesToEdges(other.xs[j], other.ys[j], xs[i], ys[i], minX[i], minY[i], maxX[i], maxY[i],
                                radius(i));
                    }
                    near = n.found;
                }
            }
        }
        return near ? limit : Double.POSITIVE_INFINITY;
    }

    /** How far apart the boxes of polygon i of this and polygon j of {@code o} are (0 if they overlap). */
    private double boxGap(int i, Outlines o, int j) {
        return Math.sqrt(boxGapSquared(i, o, j));
    }

    /**
     * {@link #boxGap} squared: whether boxes meet, without the square root (nine pairs of polygons at
     * every overlap test of two wanderers); its square root is 0 exactly when it is.
     */
    private double boxGapSquared(int i, Outlines o, int j) {
        double dx = Math.max(0.0, Math.max(minX[i] - o.maxX[j], o.minX[j] - maxX[i]));
        double dy = Math.max(0.0, Math.max(minY[i] - o.maxY[j], o.minY[j] - maxY[i]));
        return dx * dx + dy * dy;
    }

    /** Whether polygon i of this and polygon j of {@code o} overlap or touch. */
    private boolean polygonsOverlap(int i, Outlines o, int j) {
        // Where edges of the two can meet: in both boxes.
        double x0 = Math.max(minX[i], o.minX[j]);
        double y0 = Math.max(minY[i], o.minY[j]);
        double x1 = Math.min(maxX[i], o.maxX[j]);
        double y1 = Math.min(maxY[i], o.maxY[j]);
        return edgesTouch(xs[i], ys[i], o.xs[j], o.ys[j], x0, y0, x1, y1, o.near)
                || (o.inBox(j, xs[i][0], ys[i][0]) && contains(o.xs[j], o.ys[j], xs[i][0], ys[i][0]))
                || (inBox(i, o.xs[j][0], o.ys[j][0]) && contains(xs[i], ys[i], o.xs[j][0], o.ys[j][0]));
    }

    private boolean inBox(int i, double x, double y) {
        return x >= minX[i] && x <= maxX[i] && y >= minY[i] && y <= maxY[i];
    }

    /**
     * Whether an edge of polygon a touches an edge of polygon b, where [x0, x1] x [y0, y1] is where the
     * polygons' boxes meet. An edge whose box misses that box is passed over: two edges that touch have
     * boxes that meet, inside both polygons' boxes, so {@link #segmentsTouch} would turn it down against
     * every edge of the other. {@code near} has room for b's edges.
     */
    private static boolean edgesTouch(double[] ax, double[] ay, double[] bx, double[] by, double x0, double y0,
                                      double x1, double y1, int[] near) {
        if (x1 < x0 || y1 < y0) {
            return false;
        }
        int na = ax.length;
        int nb = bx.length;
        int m = 0;
        for (int j = 0; j < nb; j++) {
            int j1 = j + 1 == nb ? 0 : j + 1;
            if (!edgeMisses(bx[j], by[j], bx[j1], by[j1], x0, y0, x1, y1)) {
                near[m++] = j;
            }
        }
        if (m == 0) {
            return false;
        }
        for (int i = 0; i < na; i++) {
            int i1 = i + 1 == na ? 0 : i + 1;
            if (edgeMisses(ax[i], ay[i], ax[i1], ay[i1], x0, y0, x1, y1)) {
                continue;
            }
            for (int k = 0; k < m; k++) {
                int j = near[k];
                int j1 = j + 1 == nb ? 0 : j + 1;
                if (segmentsTouch(ax[i], ay[i], ax[i1], ay[i1], bx[j], by[j], bx[j1], by[j1])) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Whether the box of the edge (px, py)-(qx, qy) misses the box [x0, x1] x [y0, y1]: both ends on the
     * far side of one of its sides (the same as comparing the edge's least and greatest coordinates).
     */
    private static boolean edgeMisses(double px, double py, double qx, double qy, double x0, double y0, double x1,
                                      double y1) {
        return (px < x0 && qx < x0) || (px > x1 && qx > x1) || (py < y0 && qy < y0) || (py > y1 && qy > y1);
    }

    /** Whether segments p and q share a point (end points included; collinear overlap counts). */
    static boolean segmentsTouch(double px0, double py0, double px1, double py1,
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
    static boolean contains(double[] x, double[] y, double px, double py) {
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

    /**
     * The squared distance between polygon i of this and polygon j of {@code o}, which do not overlap:
     * the nearest vertex to edge, either way. Exactly that minimum when its root is below {@code limit};
     * otherwise a value whose root is at least {@code limit}. Vertex-edge pairs that cannot come below
     * the best so far are skipped (the vertex is too far from the other polygon's box or circle, or
     * from the edge's box): a minimum depends neither on the order nor on candidates that cannot win,
     * so the value is bit for bit what trying every pair gives.
     */
    private double squaredDistance(int i, Outlines o, int j, double limit) {
        Nearest n = new Nearest(limit, false);
        n.verticesToEdges(xs[i], ys[i], o.xs[j], o.ys[j], o.minX[j], o.minY[j], o.maxX[j], o.maxY[j], o.radius(j));
        n.verticesToEdges(o.xs[j], o.ys[j], xs[i], ys[i], minX[i], minY[i], maxX[i], maxY[i], radius(i));
        return n.best;
    }

    private double radius(int i) {
        if (Double.isNaN(radius[i])) {
            double cx = 0.5 * (minX[i] + maxX[i]);
            double cy = 0.5 * (minY[i] + maxY[i]);
            double r2 = 0.0;
            for (int k = 0; k < xs[i].length; k++) {
                r2 = Math.max(r2, (xs[i][k] - cx) * (xs[i][k] - cx) + (ys[i][k] - cy) * (ys[i][k] - cy));
            }
            radius[i] = Math.sqrt(r2);
        }
        return radius[i];
    }

    /** The running minimum of squared vertex-to-edge distances, and how far a candidate may be to matter. */
    private static final class Nearest {
        /**
         * Slack on the pruning bound, metres: far above the rounding of any coordinate the simulator
         * handles, so that no pair whose computed distance could win is skipped.
         */
        static final double SLACK = 1.0e-9;
        private final double limit;
        /** Whether to stop at the first vertex within {@link #limit} of an edge, which sets {@link #found}. */
        private final boolean any;
        double best = Double.POSITIVE_INFINITY;
        /** Whether a vertex within {@link #limit} of an edge was found (looked for only with {@link #any}). */
        boolean found;
        private double bound;
        /** The root of {@link #bound}. */
        private double reach;
        /** The middle of the box of the polygon whose edges are tried, and its radius about it. */
        private double cx;
        private double cy;
        private double r;

        Nearest(double limit, boolean any) {
            this.limit = limit;
            this.any = any;
            this.reach = limit + SLACK;
            this.bound = square(reach);
        }

        /**
         * Tries the vertices of p against the edges of e (whose box is [x0, x1] x [y0, y1]): first the
         * vertex nearest the middle of that box, which soon gives a bound that rules most others out.
         */
        void verticesToEdges(double[] px, double[] py, double[] ex, double[] ey, double x0, double y0, double x1,
                             double y1, double r) {
            double cx = 0.5 * (x0 + x1);
            double cy = 0.5 * (y0 + y1);
            this.cx = cx;
            this.cy = cy;
            this.r = r + SLACK;
            int first = 0;
            double nearest = Double.POSITIVE_INFINITY;
            for (int k = 0; k < px.length; k++) {
                double d = square(px[k] - cx) + square(py[k] - cy);
                if (d < nearest) {
                    nearest = d;
                    first = k;
                }
            }
            vertexToEdges(px[first], py[first], ex, ey, x0, y0, x1, y1);
            for (int k = 0; k < px.length && !found; k++) {
                if (k != first) {
                    vertexToEdges(px[k], py[k], ex, ey, x0, y0, x1, y1);
                }
            }
        }

        private void vertexToEdges(double x, double y, double[] ex, double[] ey, double x0, double y0, double x1,
                                   double y1) {
            if (square(outside(x, x0, x1)) + square(outside(y, y0, y1)) > bound
                    || square(x - cx) + square(y - cy) > square(r + reach)) {
                return;
            }
            int n = ex.length;
            for (int e = 0; e < n; e++) {
                int e1 = e + 1 == n ? 0 : e + 1;
                double ax = ex[e];
                double bx = ex[e1];
                double ay = ey[e];
                double by = ey[e1];
                double gx = outside(x, Math.min(ax, bx), Math.max(ax, bx));
                double gy = outside(y, Math.min(ay, by), Math.max(ay, by));
                if (gx * gx + gy * gy > bound) {
                    continue;
                }
                double d = squaredToSegment(x, y, ax, ay, bx, by);
                if (d < best) {
                    best = d;
                    reach = Math.min(limit, Math.sqrt(d)) + SLACK;
                    bound = square(reach);
                    if (any && Math.sqrt(d) <= limit) {
                        found = true;
                        return;
                    }
                }
            }
        }

        private static double outside(double v, double lo, double hi) {
            return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
        }

        private static double square(double v) {
            return v * v;
        }
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
