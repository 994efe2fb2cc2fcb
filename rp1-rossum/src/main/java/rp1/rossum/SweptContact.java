package rp1.rossum;

/**
 * The analytic first-contact search of behavior.md section 6.2: how far a body (given as edges at the
 * start of its motion) can move along a straight line or an arc before one of its vertices meets a
 * wall edge or a wall vertex meets one of its edges. Both directions of the test are needed: a wall
 * corner can strike the middle of a body edge without any body vertex touching the wall. Because the
 * whole path is examined at once, nothing can tunnel through a thin wall.
 */
final class SweptContact {
    /** Vertices closer than this (squared metres) to the pivot of an arc do not move and are skipped. */
    private static final double PIVOT_SQUARED = 1.0e-6;
    private static final double TWO_PI = 2.0 * Math.PI;
    /**
     * Slack, relative to the size of the coordinates, of the test that a wall is out of reach: far
     * more than the rounding of the contact tests, so a wall it skips has no contact to find.
     */
    private static final double OUT_OF_REACH_SLACK = 1.0e-6;
    /**
     * Slack, relative to the size of the coordinates and of the displacement, of the test that walls
     * lie beyond a contact already found: far more than the rounding of a contact's fraction.
     */
    private static final double ROUNDING_SLACK = 1.0e-9;
    /**
     * Slack, relative to the size of the coordinates, of the test that a mover's line of travel misses
     * an edge: far more than the rounding of the intersection test, so a pair it skips has no
     * intersection to find.
     */
    private static final double ACROSS_SLACK = 1.0e-9;
    /** The places in what {@link #extents} gives. */
    private static final int BACK = 0;
    private static final int FRONT = 1;
    private static final int RIGHT = 2;
    private static final int LEFT = 3;
    private static final int SIZE = 4;

    private SweptContact() {
    }

    /**
     * The smallest fraction f in [0, 1] of the displacement (dx, dy) at which the body touches a wall,
     * or positive infinity if it does not.
     */
    static double line(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double dx, double dy) {
        return line(body, nBody, walls, nWalls, dx, dy, null);
    }

    /**
     * {@link #line}, given the body's {@link #bodyExtents} for this displacement (or null): a search
     * of one body against many walls works them out once.
     */
    static double line(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double dx, double dy,
                       double[] bodyExtents) {
        if (outOfLineBand(body, nBody, walls, nWalls, dx, dy, bodyExtents)
                || outOfLineReach(body, nBody, walls, nWalls, dx, dy)) {
            return Double.POSITIVE_INFINITY;
        }
        return lineSearch(body, nBody, walls, nWalls, dx, dy);
    }

    /**
     * How far the body reaches along the displacement (dx, dy) and across it, as {@link #outOfLineBand}
     * and {@link #lineBeyond} need them for every wall; null where they work without (no displacement,
     * or one too long to square).
     */
    static double[] bodyExtents(RsSegment[] body, int nBody, double dx, double dy) {
        double length = length(dx, dy);
        if (nBody == 0 || !(length > 0.0) || length == Double.POSITIVE_INFINITY) {
            return null;
        }
        return extents(body, nBody, dx / length, dy / length);
    }

    /**
     * The length of (dx, dy), as Math.hypot gives it to within a rounding, without its cost (it was 1 %
     * of a crowd's time): where the squares overflow or underflow, Math.hypot itself. The searches use
     * a displacement's length only to say which pairs of edges or walls could meet, with a slack far
     * above a rounding, never for a contact's time.
     */
    private static double length(double dx, double dy) {
        double squared = dx * dx + dy * dy;
        return squared >= Double.MIN_NORMAL && squared < Double.POSITIVE_INFINITY ? Math.sqrt(squared)
                : Math.hypot(dx, dy);
    }

    /**
     * Whether the walls lie wholly beside the band the body sweeps, wholly behind the body or wholly
     * beyond where it ends, in the axes of the travel (dx, dy): no point of the body then crosses a
     * wall edge nor a wall point a body edge, so {@link #lineSearch} would find nothing. Sharper than
     * {@link #outOfLineReach}, whose disc about the body's first vertex is a round body's diameter wide
     * on either side of the path: in a crowd's arena (1,000 robots, 49 pillars) the walls that test
     * let through had no contact in two searches of five, and this one lets through 1 in 70 of those.
     */
    static boolean outOfLineBand(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double dx, double dy) {
        return outOfLineBand(body, nBody, walls, nWalls, dx, dy, null);
    }

    private static boolean outOfLineBand(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double dx,
                                         double dy, double[] bodyExtents) {
        double[] b = bodyExtents != null ? bodyExtents : bodyExtents(body, nBody, dx, dy);
        if (b == null) {
            return false;
        }
        double length = length(dx, dy);
        double[] w = extents(walls, nWalls, dx / length, dy / length);
        double slack = OUT_OF_REACH_SLACK * (1.0 + Math.max(b[SIZE], w[SIZE]));
        return w[RIGHT] > b[LEFT] + slack || w[LEFT] < b[RIGHT] - slack || w[FRONT] < b[BACK] - slack
                || w[BACK] > b[FRONT] + length + slack + OUT_OF_REACH_SLACK * length;
    }

    /**
     * How far the ends of the edges reach along the direction (ux, uy) and across it (to its left), the
     * least and the most of each, and the largest sum of an edge's coordinates' sizes (for the slack).
     * Comparisons rather than Math.min and Math.max, which the quick compiler's code (a sweep's runs)
     * calls; a NaN is passed over, and edges of NaNs have no contact to find.
     */
    private static double[] extents(RsSegment[] edges, int n, double ux, double uy) {
        double back = Double.POSITIVE_INFINITY;
        double front = Double.NEGATIVE_INFINITY;
        double right = Double.POSITIVE_INFINITY;
        double left = Double.NEGATIVE_INFINITY;
        double size = 0.0;
        for (int i = 0; i < n; i++) {
            RsSegment e = edges[i];
            for (int end = 0; end < 2; end++) {
                double x = end == 0 ? e.x : e.x + e.v.x;
                double y = end == 0 ? e.y : e.y + e.v.y;
                double along = x * ux + y * uy;
                double across = y * ux - x * uy;
                back = along < back ? along : back;
                front = along > front ? along : front;
                right = across < right ? across : right;
                left = across > left ? across : left;
            }
            double extent = Math.abs(e.x) + Math.abs(e.y) + Math.abs(e.v.x) + Math.abs(e.v.y);
            size = extent > size ? extent : size;
        }
        return new double[] {back, front, right, left, size};
    }

    /**
     * {@link #extents}' back alone: the least reach of the edges' ends along (ux, uy). A contact search
     * asks it of every wall once it has a contact, and needs nothing across.
     */
    private static double leastAlong(RsSegment[] edges, int n, double ux, double uy) {
        double back = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            RsSegment e = edges[i];
            double a = e.x * ux + e.y * uy;
            double b = (e.x + e.v.x) * ux + (e.y + e.v.y) * uy;
            back = a < back ? a : back;
            back = b < back ? b : back;
        }
        return back;
    }

    /**
     * Whether the walls lie wholly beyond the point the body reaches at {@code fraction} of the
     * displacement (dx, dy): along the direction of travel, their nearest vertex is farther ahead of
     * the body's foremost vertex than that, so {@link #line} could only find a later contact. A
     * search that has found a contact skips such walls.
     */
    static boolean lineBeyond(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                              double dx, double dy, double fraction) {
        return lineBeyond(body, nBody, walls, nWalls, dx, dy, fraction, null);
    }

    /** {@link #lineBeyond}, given the body's {@link #bodyExtents} for this displacement (or null). */
    static boolean lineBeyond(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                              double dx, double dy, double fraction, double[] bodyExtents) {
        double length = length(dx, dy);
        if (length == 0.0 || nBody == 0 || nWalls == 0) {
            return false;
        }
        double ux = dx / length;
        double uy = dy / length;
        double front = (bodyExtents != null ? bodyExtents : extents(body, nBody, ux, uy))[FRONT];
        double back = leastAlong(walls, nWalls, ux, uy);
        double slack = ROUNDING_SLACK * (1.0 + Math.abs(body[0].x) + Math.abs(body[0].y) + length);
        return back - front > fraction * length + slack;
    }

    /** {@link #line} without first skipping walls out of reach: every pair of edges is tested. */
    static double lineSearch(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double dx, double dy) {
        return Math.min(sweep(body, nBody, walls, nWalls, dx, dy), sweep(walls, nWalls, body, nBody, -dx, -dy));
    }

    /**
     * Moves every start point of {@code movers} by (dx, dy) and intersects the path with {@code edges}.
     * A point meets an edge only where its line of travel crosses the edge, that is, where its place
     * across the direction of travel lies within the edge's extent across it; the intersection is
     * computed only for those pairs (most of a body's vertices pass beside a wall's edge).
     */
    private static double sweep(RsSegment[] movers, int nMovers, RsSegment[] edges, int nEdges, double dx, double dy) {
        double length = length(dx, dy);
        if (length == 0.0) {
            return Double.POSITIVE_INFINITY;
        }
        // The unit normal of the direction of travel: a point's place across it.
        double nx = -dy / length;
        double ny = dx / length;
        double moversSize = 0.0;
        for (int i = 0; i < nMovers; i++) {
            moversSize = Math.max(moversSize, Math.abs(movers[i].x) + Math.abs(movers[i].y));
        }
        RsSegSect sect = new RsSegSect();
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < nEdges; j++) {
            RsSegment e = edges[j];
            double a = nx * e.x + ny * e.y;
            double b = nx * (e.x + e.v.x) + ny * (e.y + e.v.y);
            double slack = ACROSS_SLACK
                    * (1.0 + moversSize + Math.abs(e.x) + Math.abs(e.y) + Math.abs(e.v.x) + Math.abs(e.v.y));
            double lo = Math.min(a, b) - slack;
            double hi = Math.max(a, b) + slack;
            for (int i = 0; i < nMovers; i++) {
                RsSegment p = movers[i];
                double across = nx * p.x + ny * p.y;
                if (across < lo || across > hi) {
                    continue;
                }
                if (sect.process(p.x, p.y, dx, dy, e.x, e.y, e.v.x, e.v.y) && sect.t1 < best) {
                    best = sect.t1;
                }
            }
        }
        return best;
    }

    /**
     * The smallest fraction of {@code totalAngle} (radians, positive counter-clockwise) through which the
     * body can turn about (cx, cy) before it touches a wall, or positive infinity. Only one revolution
     * is examined.
     */
    static double arc(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                      double cx, double cy, double totalAngle) {
        if (totalAngle == 0.0) {
            return Double.POSITIVE_INFINITY;
        }
        if (outOfArcReach(body, nBody, walls, nWalls, cx, cy)) {
            return Double.POSITIVE_INFINITY;
        }
        return arcSearch(body, nBody, walls, nWalls, cx, cy, totalAngle);
    }

    /** {@link #arc} without first skipping walls out of reach: every pair of edges is tested. */
    static double arcSearch(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                            double cx, double cy, double totalAngle) {
        double direction = Math.signum(totalAngle);
        double swept = Math.min(
                turn(body, nBody, walls, nWalls, cx, cy, direction),
                turn(walls, nWalls, body, nBody, cx, cy, -direction));
        double limit = Math.abs(totalAngle);
        return swept <= limit ? swept / limit : Double.POSITIVE_INFINITY;
    }

    /** The smallest angle through which a start point of {@code movers} turns before meeting {@code edges}. */
    private static double turn(RsSegment[] movers, int nMovers, RsSegment[] edges, int nEdges,
                               double cx, double cy, double direction) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < nMovers; i++) {
            double px = movers[i].x - cx;
            double py = movers[i].y - cy;
            double r2 = px * px + py * py;
            if (r2 < PIVOT_SQUARED) {
                continue;
            }
            for (int j = 0; j < nEdges; j++) {
                best = Math.min(best, angleToEdge(px, py, r2, edges[j], cx, cy, direction));
            }
        }
        return best;
    }

    /**
     * The angle in [0, 2 pi) that the point (px, py) (relative to the pivot) turns in {@code direction}
     * before its circle of squared radius r2 meets edge {@code e}, or positive infinity if it never does.
     */
    private static double angleToEdge(double px, double py, double r2, RsSegment e,
                                      double cx, double cy, double direction) {
        double ex = e.x - cx;
        double ey = e.y - cy;
        double a = e.v.x * e.v.x + e.v.y * e.v.y;
        if (a == 0.0) {
            return Double.POSITIVE_INFINITY;
        }
        double b = 2.0 * (ex * e.v.x + ey * e.v.y);
        double c = ex * ex + ey * ey - r2;
        double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) {
            return Double.POSITIVE_INFINITY;
        }
        double root = Math.sqrt(disc);
        return Math.min(
                angleAt((-b - root) / (2.0 * a), px, py, ex, ey, e, direction),
                angleAt((-b + root) / (2.0 * a), px, py, ex, ey, e, direction));
    }

    /** The turn from (px, py) to the point at fraction u of the edge, if u lies on the edge. */
    private static double angleAt(double u, double px, double py, double ex, double ey, RsSegment e, double direction) {
        if (u < 0.0 || u > 1.0) {
            return Double.POSITIVE_INFINITY;
        }
        double qx = ex + u * e.v.x;
        double qy = ey + u * e.v.y;
        double angle = direction * Math.atan2(px * qy - py * qx, px * qx + py * qy);
        return angle < 0.0 ? angle + TWO_PI : angle;
    }

    /**
     * Whether no wall edge comes near the path of the body: the body lies in a disc about its first
     * vertex, and every wall edge is farther from the segment that disc's centre travels than its
     * radius. Most walls near a long path are, and skipping them skips the pairwise search.
     */
    private static boolean outOfLineReach(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                                          double dx, double dy) {
        if (nBody == 0) {
            return true;
        }
        double ox = body[0].x;
        double oy = body[0].y;
        double radius = Math.sqrt(farthestSquared(body, nBody, ox, oy));
        double reach = radius + slack(ox, oy, radius + Math.abs(dx) + Math.abs(dy));
        double x0 = Math.min(ox, ox + dx) - reach;
        double x1 = Math.max(ox, ox + dx) + reach;
        double y0 = Math.min(oy, oy + dy) - reach;
        double y1 = Math.max(oy, oy + dy) + reach;
        for (int j = 0; j < nWalls; j++) {
            RsSegment e = walls[j];
            if (boxesMeet(e, x0, y0, x1, y1)
                    && segmentsDistanceSquared(ox, oy, dx, dy, e.x, e.y, e.v.x, e.v.y) <= reach * reach) {
                return false;
            }
        }
        return true;
    }

    /**
     * Whether no wall edge comes within the circle about the pivot that holds the whole body, which
     * no part of the body leaves while it turns.
     */
    private static boolean outOfArcReach(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls,
                                         double cx, double cy) {
        double radius = Math.sqrt(farthestSquared(body, nBody, cx, cy));
        double reach = radius + slack(cx, cy, radius);
        for (int j = 0; j < nWalls; j++) {
            RsSegment e = walls[j];
            if (boxesMeet(e, cx - reach, cy - reach, cx + reach, cy + reach)
                    && pointSegmentDistanceSquared(cx, cy, e.x, e.y, e.v.x, e.v.y) <= reach * reach) {
                return false;
            }
        }
        return true;
    }

    /** Whether the segment's bounding box meets the box [x0, x1] x [y0, y1]: a cheap first test. */
    private static boolean boxesMeet(RsSegment e, double x0, double y0, double x1, double y1) {
        double ex1 = e.x + e.v.x;
        double ey1 = e.y + e.v.y;
        return Math.max(e.x, ex1) >= x0 && Math.min(e.x, ex1) <= x1 && Math.max(e.y, ey1) >= y0 && Math.min(e.y, ey1) <= y1;
    }

    private static double slack(double x, double y, double size) {
        return OUT_OF_REACH_SLACK * (1.0 + Math.abs(x) + Math.abs(y) + size);
    }

    /** The largest squared distance from (x, y) to either end of the segments. */
    private static double farthestSquared(RsSegment[] segments, int n, double x, double y) {
        double most = 0.0;
        for (int i = 0; i < n; i++) {
            RsSegment s = segments[i];
            double ax = s.x - x;
            double ay = s.y - y;
            double bx = ax + s.v.x;
            double by = ay + s.v.y;
            double a = ax * ax + ay * ay;
            double b = bx * bx + by * by;
            // Math.max without the call the quick compiler's code makes (a sweep's runs): a NaN wins.
            most = a > most || a != a ? a : most;
            most = b > most || b != b ? b : most;
        }
        return most;
    }

    /** The squared distance from (px, py) to the segment from (x, y) along (vx, vy). */
    private static double pointSegmentDistanceSquared(double px, double py, double x, double y, double vx, double vy) {
        double wx = px - x;
        double wy = py - y;
        double length = vx * vx + vy * vy;
        double u = length > 0.0 ? Math.max(0.0, Math.min(1.0, (wx * vx + wy * vy) / length)) : 0.0;
        double ex = wx - u * vx;
        double ey = wy - u * vy;
        return ex * ex + ey * ey;
    }

    /** The squared distance between two segments, each from a point along a vector (0 if they cross). */
    private static double segmentsDistanceSquared(double ax, double ay, double avx, double avy,
                                                  double bx, double by, double bvx, double bvy) {
        double det = avx * bvy - avy * bvx;
        if (det != 0.0) {
            double ex = bx - ax;
            double ey = by - ay;
            double u = (ex * bvy - ey * bvx) / det;
            double w = (ex * avy - ey * avx) / det;
            if (u >= 0.0 && u <= 1.0 && w >= 0.0 && w <= 1.0) {
                return 0.0;
            }
        }
        return Math.min(
                Math.min(pointSegmentDistanceSquared(ax, ay, bx, by, bvx, bvy),
                        pointSegmentDistanceSquared(ax + avx, ay + avy, bx, by, bvx, bvy)),
                Math.min(pointSegmentDistanceSquared(bx, by, ax, ay, avx, avy),
                        pointSegmentDistanceSquared(bx + bvx, by + bvy, ax, ay, avx, avy)));
    }
}
