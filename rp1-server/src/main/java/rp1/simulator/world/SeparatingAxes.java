package rp1.simulator.world;

import rp1.rossum.RsTransform;

/**
 * Cheap answers for the contact search's samples of robots pressed against each other, where the
 * circles around the bodies overlap and placing both robots' outlines and testing their edges was
 * most of a crowd's time. Each answer is one {@link Outlines} would give, found from a few vertices
 * instead of all of them; where none is found the caller asks {@link Outlines}, so the search decides
 * exactly what it decided without this. {@link #look} tries, for each pair of polygons of the two
 * robots whose circles meet:
 *
 * <ul>
 *   <li>a line that separates them with room to spare ({@link #margin}), which shows that they neither
 *   overlap nor touch: the last line that did for the pair, the line between their centres, and the
 *   edges of their hulls ({@link Hull}) beside where each comes nearest the other along that line,
 *   each a few dot products in the robots' own coordinates;</li>
 *   <li>failing the line between the centres, two edges that touch beside where each polygon comes
 *   nearest the other along it, which shows the robots touching.</li>
 * </ul>
 * After all pairs were shown apart, {@link #near} looks for a vertex within a distance of an edge, as
 * {@link Outlines#within} does.
 *
 * <p>Room to spare means a margin far above what rounding can do to a placed vertex or to an edge
 * test. {@link Outlines#segmentsTouch} tells apart two edges on either side of a strip of width
 * {@code m} unless the rounding of its cross products (about {@code 2e-15} times the coordinates' size
 * {@code C} times an edge's length {@code E}) exceeds what the strip forces on them: the edges must
 * then be so nearly in line that their boxes are apart, which holds while {@code m} squared is above
 * about {@code 1e-14} times {@code C} and {@code E}. {@link #margin} is ten times that.
 *
 * <p>What it keeps from one question to the next (the last separating line) only saves work: the
 * answers are the same without it.
 */
final class SeparatingAxes {
    /** {@link #look} found nothing: ask {@link Outlines}. */
    static final int UNKNOWN = 0;
    /** {@link #look} found the robots apart: {@link Outlines#overlaps} says false. */
    static final int APART = 1;
    /** {@link #look} found the robots touching: {@link Outlines#overlaps} says true. */
    static final int TOUCHING = 2;

    /** Least margin, metres. */
    private static final double MARGIN = 1.0e-9;
    /** The margin squared, per square metre of the coordinates' size times an edge's length. */
    private static final double MARGIN_SQUARED = 1.0e-13;
    /**
     * Slack of the bounds of {@link #distance} and {@link #lookBeyond}, per metre of the coordinates'
     * size: far above rounding.
     */
    private static final double SLACK = 1.0e-9;
    /** Most vertices {@link #distance} takes from one polygon. */
    private static final int MOST_NEAR = 9;

    /**
     * After {@link #gap}: the direction it measured along, in the plane and in each body's coordinates
     * (b's turned round, pointing back at a), and the vertex of each hull nearest the other along it.
     */
    private double directionX;
    private double directionY;
    private double localAX;
    private double localAY;
    private double localBX;
    private double localBY;
    private int nearestA;
    private int nearestB;
    /** After {@link #between}: how far the centre of one hull lies from the other's, in the plane. */
    private double betweenX;
    private double betweenY;
    /**
     * The last line that separated a pair of polygons, as a direction in the plane, and which pair:
     * the search asks about the same two robots sample after sample, and they move little between.
     */
    private Object lineA;
    private Object lineB;
    private int lineI;
    private int lineJ;
    private double lineX;
    private double lineY;
    /**
     * After {@link #look} found the robots apart: of the pairs of polygons it had to look at (their
     * circles meet), the one it found closest, and where they came nearest (polygon -1: none).
     */
    private int closestA;
    private int closestB;
    private int closestVertexA;
    private int closestVertexB;
    private double closest;

    /**
     * The two things {@link #look} was last asked about: something to know each by, the hulls of their
     * polygons, the polygons (body coordinates), and how far from their origin they reach.
     */
    private Object a;
    private Hull[] as;
    private double[][] oa;
    private double reachA;
    private Object b;
    private Hull[] bs;
    private double[][] ob;
    private double reachB;

    /** Room for a few placed vertices of either polygon ({@link #placeAround}, {@link #placeArc}). */
    private final double[] corners = new double[6];
    private final double[] others = new double[6];
    private final double[] arcCornersA = new double[2 * (MOST_NEAR + 2)];
    private final double[] arcCornersB = new double[2 * (MOST_NEAR + 2)];
    /** Room for the arcs {@link #front} finds. */
    private final int[] frontA = new int[2];
    private final int[] frontB = new int[2];

    /**
     * Whether {@code a}'s outlines at {@code pa} and {@code b}'s at {@code pb} are apart or touching, as
     * {@link Outlines#overlaps} would say, or {@link #UNKNOWN}.
     */
    int look(Robot a, RsTransform pa, Robot b, RsTransform pb) {
        RobotShapes sa = a.shapes();
        RobotShapes sb = b.shapes();
        return look(a, sa.hulls(), sa.outlines(), sa.reach(), pa, b, sb.hulls(), sb.outlines(), sb.reach(), pb, 0.0);
    }

    /**
     * Whether contact sensor {@code sensor} (its outline {@code outline} with its hull, reaching
     * {@code reach} from the body origin) at {@code pose} is further than {@code limit} from robot
     * {@code b}'s outlines at {@code pb} as {@link Outlines#distance(Outlines, double)} would measure it
     * ({@link #APART}), touches them ({@link #TOUCHING}: a distance of 0), or {@link #UNKNOWN}.
     */
    int lookBeyond(Object sensor, Hull[] hull, double[][] outline, double reach, RsTransform pose, Robot b,
                   RsTransform pb, double limit) {
        RobotShapes sb = b.shapes();
        // Far more than rounding beyond the limit: the computed distance is then beyond it too.
        double beyond = limit + SLACK * (1.0 + Math.abs(pose.m13) + Math.abs(pose.m23));
        return look(sensor, hull, outline, reach, pose, b, sb.hulls(), sb.outlines(), sb.reach(), pb, beyond);
    }

    /**
     * Whether polygons {@code oa} (body coordinates, their hulls {@code as}, reaching {@code reachA} from
     * the origin) at {@code pa} and polygons {@code ob} at {@code pb} are apart or touching, as
     * {@link Outlines#overlaps} would say, or {@link #UNKNOWN}; {@code a} and {@code b} are what they
     * are the outlines of (the last line that separated them is tried first when asked again).
     */
    private int look(Object a, Hull[] as, double[][] oa, double reachA, RsTransform pa, Object b, Hull[] bs,
                     double[][] ob, double reachB, RsTransform pb, double beyond) {
        this.a = a;
        this.as = as;
        this.oa = oa;
        this.reachA = reachA;
        this.b = b;
        this.bs = bs;
        this.ob = ob;
        this.reachB = reachB;
        double margin = Math.max(margin(pa, pb), beyond);
        closestA = -1;
        closest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < as.length; i++) {
            Hull ha = as[i];
            for (int j = 0; j < bs.length; j++) {
                Hull hb = bs[j];
                double d = between(ha, pa, hb, pb);
                if (d - ha.radius() - hb.radius() >= margin || ha.size() == 0 || hb.size() == 0) {
                    continue;
                }
                int found = look(pa, ha, i, pb, hb, j, betweenX, betweenY, d, margin);
                if (found != APART) {
                    return found;
                }
            }
        }
        return APART;
    }

    /**
     * Polygon i of a (hull {@code ha}) against polygon j of b (hull {@code hb}), whose centres are (dx,
     * dy) apart, d in all: {@link #APART} if a line separates them, {@link #TOUCHING} if two of their
     * edges touch, else {@link #UNKNOWN}.
     */
    private int look(RsTransform pa, Hull ha, int i, RsTransform pb, Hull hb, int j, double dx, double dy, double d,
                     double margin) {
        if (a == lineA && b == lineB && i == lineI && j == lineJ) {
            double gap = gap(ha, pa, hb, pb, dx, dy, lineX, lineY);
            if (gap >= margin) {
                return apart(i, j, gap);
            }
        }
        if (!(d > 0.0)) {
            return UNKNOWN;
        }
        double gap = gap(ha, pa, hb, pb, dx, dy, dx / d, dy / d);
        if (gap >= margin) {
            return remember(i, j, gap);
        }
        // Where each comes nearest the other: two edges there that touch show the robots touching;
        // two convex polygons close together and apart are best separated along one of those edges.
        int va = nearestA;
        int vb = nearestB;
        if (crossing(oa[i], ha.vertex(va), pa, ob[j], hb.vertex(vb), pb)) {
            return TOUCHING;
        }
        for (int k = 0; k < 4; k++) {
            Hull h = k < 2 ? ha : hb;
            RsTransform p = k < 2 ? pa : pb;
            if (!h.hasEdges()) {
                continue;
            }
            int v = k < 2 ? va : vb;
            int edge = k % 2 == 0 ? h.previous(v) : v;
            double nx = p.m11 * h.normalX(edge) + p.m12 * h.normalY(edge);
            double ny = p.m21 * h.normalX(edge) + p.m22 * h.normalY(edge);
            // b's outward normals point towards a.
            double scale = (k < 2 ? 1.0 : -1.0) / Math.sqrt(nx * nx + ny * ny);
            gap = gap(ha, pa, hb, pb, dx, dy, nx * scale, ny * scale);
            if (gap >= margin) {
                return remember(i, j, gap);
            }
        }
        return UNKNOWN;
    }

    /** The line just measured along separates polygons i and j: kept for the next question about them. */
    private int remember(int i, int j, double gap) {
        lineA = a;
        lineB = b;
        lineI = i;
        lineJ = j;
        lineX = directionX;
        lineY = directionY;
        return apart(i, j, gap);
    }

    /** Polygons i and j are apart by {@code gap}: keeps them if they are the closest pair so far. */
    private int apart(int i, int j, double gap) {
        if (gap < closest) {
            closest = gap;
            closestA = i;
            closestB = j;
            closestVertexA = nearestA;
            closestVertexB = nearestB;
        }
        return APART;
    }

    /**
     * How far apart hull {@code ha} at {@code pa} and hull {@code hb} at {@code pb} lie along the unit direction (ux, uy), from a's side towards b's, with the centre of
     * b's at (dx, dy) from a's; sets the nearest vertices.
     */
    private double gap(Hull ha, RsTransform pa, Hull hb, RsTransform pb, double dx, double dy, double ux,
                       double uy) {
        // The direction in each body's coordinates: the pose's rotation transposed.
        double ax = pa.m11 * ux + pa.m21 * uy;
        double ay = pa.m12 * ux + pa.m22 * uy;
        double bx = -(pb.m11 * ux + pb.m21 * uy);
        double by = -(pb.m12 * ux + pb.m22 * uy);
        directionX = ux;
        directionY = uy;
        localAX = ax;
        localAY = ay;
        localBX = bx;
        localBY = by;
        nearestA = ha.farthest(ax, ay);
        nearestB = hb.farthest(bx, by);
        // Measured from the centres, which the hulls' coordinates are not: subtract theirs.
        return dx * ux + dy * uy - (ha.along(nearestA, ax, ay) - ha.centreAlong(ax, ay))
                - (hb.along(nearestB, bx, by) - hb.centreAlong(bx, by));
    }

    /**
     * Whether an edge beside vertex k of polygon {@code p} at {@code pp} touches an edge beside vertex
     * m of polygon {@code q} at {@code pq}, with the test {@link Outlines#overlaps} makes of two edges
     * and on the placed coordinates it makes it on; so if this says so, so does {@code overlaps} (which
     * cannot pass over two edges that touch).
     */
    private boolean crossing(double[] p, int k, RsTransform pp, double[] q, int m, RsTransform pq) {
        if (p.length < 4 || q.length < 4) {
            return false;
        }
        double[] a = placeAround(p, k, pp, corners);
        double[] b = placeAround(q, m, pq, others);
        for (int e = 0; e < 4; e += 2) {
            for (int f = 0; f < 4; f += 2) {
                if (Outlines.segmentsTouch(a[e], a[e + 1], a[e + 2], a[e + 3], b[f], b[f + 1], b[f + 2], b[f + 3])) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * After {@link #look} found the two apart (at the same poses): whether, in the pair of polygons it
     * found closest of those whose circles meet, the vertex of either nearest the other is within {@code limit} of an
     * edge beside the other's nearest vertex. Computed from the placed coordinates {@link Outlines#place}
     * would give, with the distance {@link Outlines#within} computes for that vertex and edge, so that if
     * this says so, so does {@code within}, which looks at every vertex and edge. False says nothing.
     */
    boolean near(RsTransform pa, RsTransform pb, double limit) {
        if (closestA < 0) {
            return false;
        }
        double[] p = placeAround(oa[closestA], as[closestA].vertex(closestVertexA), pa, corners);
        double[] q = placeAround(ob[closestB], bs[closestB].vertex(closestVertexB), pb, others);
        return within(p[2], p[3], q, 0, limit) || within(p[2], p[3], q, 2, limit)
                || within(q[2], q[3], p, 0, limit) || within(q[2], q[3], p, 2, limit);
    }

    /**
     * After {@link #look} found the two apart (at the same poses): the distance between their outlines,
     * bit for bit what
     * {@link Outlines#distance(Outlines)} gives, or NaN where a few vertices cannot settle it (a polygon
     * that is not convex, many vertices about as near as the nearest).
     *
     * <p>That distance is the least of the distances of every vertex of either robot to every edge of
     * the other's polygons. Along the line u from the centre of one polygon of a to one of b's, a vertex
     * of a's lies no nearer to b's than the gap between the two along u, plus how far behind a's
     * foremost vertex it lies, plus how far behind b's foremost vertex the nearest end of the edge
     * lies. So once some vertex and edge are known to be c apart, only the vertices within c - gap of
     * the front of either polygon, and the edges they end, can be nearer; they are few, follow one
     * another round a convex polygon, and are all computed here as {@link Outlines} computes them, on
     * the coordinates it places.
     */
    double distance(RsTransform pa, RsTransform pb) {
        double slack = SLACK * (1.0 + size(pa, pb));
        // Some vertex and edge first: where the pair of polygons whose circles come nearest is nearest.
        int nearI = -1;
        int nearJ = -1;
        double least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < as.length; i++) {
            for (int j = 0; j < bs.length; j++) {
                double circles = circlesGap(as[i], pa, bs[j], pb);
                if (circles < least && as[i].size() > 0 && bs[j].size() > 0) {
                    least = circles;
                    nearI = i;
                    nearJ = j;
                }
            }
        }
        if (nearI < 0 || Double.isNaN(gapBetween(as[nearI], pa, bs[nearJ], pb))) {
            return Double.NaN;
        }
        double[] p = placeAround(oa[nearI], as[nearI].vertex(nearestA), pa, corners);
        double[] q = placeAround(ob[nearJ], bs[nearJ].vertex(nearestB), pb, others);
        double best = Math.min(Math.min(squared(p[2], p[3], q, 0), squared(p[2], p[3], q, 2)),
                Math.min(squared(q[2], q[3], p, 0), squared(q[2], q[3], p, 2)));
        double c = Math.sqrt(best);
        // Then every vertex and edge that could be nearer than that, in every pair of polygons.
        for (int i = 0; i < as.length; i++) {
            for (int j = 0; j < bs.length; j++) {
                Hull ha = as[i];
                Hull hb = bs[j];
                if (ha.size() == 0 || hb.size() == 0 || circlesGap(ha, pa, hb, pb) > c + slack) {
                    continue;
                }
                double gap = gapBetween(ha, pa, hb, pb);
                if (Double.isNaN(gap) || !ha.convex() || !hb.convex()) {
                    return Double.NaN;
                }
                double reach = c - gap + slack;
                int[] arcA = front(oa[i], ha.vertex(nearestA), localAX, localAY, reach, frontA);
                int[] arcB = front(ob[j], hb.vertex(nearestB), localBX, localBY, reach, frontB);
                if (arcA == null || arcB == null) {
                    return Double.NaN;
                }
                double[] xa = placeArc(oa[i], arcA, pa, arcCornersA);
                double[] xb = placeArc(ob[j], arcB, pb, arcCornersB);
                best = Math.min(best, Math.min(nearest(xa, arcA[1], xb, arcB[1]), nearest(xb, arcB[1], xa, arcA[1])));
            }
        }
        return Math.sqrt(best);
    }

    /**
     * How far the centre of hull {@code hb} at {@code pb} lies from that of {@code ha} at {@code pa};
     * sets {@link #betweenX} and {@link #betweenY}.
     */
    private double between(Hull ha, RsTransform pa, Hull hb, RsTransform pb) {
        betweenX = placedX(pb, hb.centreX(), hb.centreY()) - placedX(pa, ha.centreX(), ha.centreY());
        betweenY = placedY(pb, hb.centreX(), hb.centreY()) - placedY(pa, ha.centreX(), ha.centreY());
        return Math.sqrt(betweenX * betweenX + betweenY * betweenY); // Math.hypot guards against overflow, at a cost
    }

    /** How far apart the circles around polygon hulls {@code ha} at {@code pa} and {@code hb} at {@code pb} are. */
    private double circlesGap(Hull ha, RsTransform pa, Hull hb, RsTransform pb) {
        return between(ha, pa, hb, pb) - ha.radius() - hb.radius();
    }

    /**
     * The gap between hulls {@code ha} and {@code hb} along the line between their centres; the
     * directions in each body's coordinates and the nearest vertices are set (see {@link #gap}). NaN if
     * the centres coincide.
     */
    private double gapBetween(Hull ha, RsTransform pa, Hull hb, RsTransform pb) {
        double d = between(ha, pa, hb, pb);
        return d > 0.0 ? gap(ha, pa, hb, pb, betweenX, betweenY, betweenX / d, betweenY / d) : Double.NaN;
    }

    /**
     * The vertices of convex {@code polygon} within {@code reach} of its foremost vertex {@code k} along
     * (dx, dy), which follow one another round it: the first and how many, in {@code arc}; null if there
     * are more than {@link #MOST_NEAR}.
     */
    private static int[] front(double[] polygon, int k, double dx, double dy, double reach, int[] arc) {
        int n = polygon.length / 2;
        double foremost = polygon[2 * k] * dx + polygon[2 * k + 1] * dy;
        int ahead = 0;
        while (ahead + 1 < n && foremost - along(polygon, (k + ahead + 1) % n, dx, dy) <= reach) {
            ahead++;
        }
        int behind = 0;
        while (ahead + behind + 1 < n && foremost - along(polygon, (k - behind - 1 + n) % n, dx, dy) <= reach) {
            behind++;
        }
        if (ahead + behind + 1 > MOST_NEAR) {
            return null;
        }
        arc[0] = (k - behind + n) % n;
        arc[1] = ahead + behind + 1;
        return arc;
    }

    private static double along(double[] polygon, int k, double dx, double dy) {
        return polygon[2 * k] * dx + polygon[2 * k + 1] * dy;
    }

    /**
     * The vertices of an arc of {@code polygon} ({@code arc}: the first and how many) with the vertex
     * before it and the one after, placed at {@code p} as {@link Outlines#place} places them, into
     * {@code xy}: the arc's vertices are at 1 to count, and the edges they end run from each to the next.
     */
    private static double[] placeArc(double[] polygon, int[] arc, RsTransform p, double[] xy) {
        int n = polygon.length / 2;
        for (int m = 0; m < arc[1] + 2; m++) {
            place(polygon, (arc[0] - 1 + m + n) % n, p, xy, 2 * m);
        }
        return xy;
    }

    /**
     * The least squared distance from the {@code count} vertices at 1 to count of {@code xy} to the
     * edges ending at the {@code others} vertices at 1 to others of {@code exy}, as {@link Outlines}
     * computes each.
     */
    private static double nearest(double[] xy, int count, double[] exy, int others) {
        double best = Double.POSITIVE_INFINITY;
        for (int v = 1; v <= count; v++) {
            for (int e = 0; e <= others; e++) {
                best = Math.min(best, squared(xy[2 * v], xy[2 * v + 1], exy, 2 * e));
            }
        }
        return best;
    }

    /** The squared distance from (x, y) to the edge from the vertex at {@code e} in {@code xy} to the next. */
    private static double squared(double x, double y, double[] xy, int e) {
        return Outlines.squaredToSegment(x, y, xy[e], xy[e + 1], xy[e + 2], xy[e + 3]);
    }

    /** Whether (x, y) is within {@code limit} of the edge from the vertex at {@code e} in {@code xy} to the next. */
    private static boolean within(double x, double y, double[] xy, int e, double limit) {
        return Math.sqrt(squared(x, y, xy, e)) <= limit;
    }

    /**
     * Vertex k of {@code polygon} and the vertices before and after it, placed at {@code p} as
     * {@link Outlines#place} places them, into {@code xy} (x, y of each in that order): its two edges
     * run in the polygon's own direction, as {@link Outlines} takes them.
     */
    private static double[] placeAround(double[] polygon, int k, RsTransform p, double[] xy) {
        int n = polygon.length / 2;
        place(polygon, k == 0 ? n - 1 : k - 1, p, xy, 0);
        place(polygon, k, p, xy, 2);
        place(polygon, k + 1 == n ? 0 : k + 1, p, xy, 4);
        return xy;
    }

    private static void place(double[] polygon, int k, RsTransform p, double[] xy, int at) {
        xy[at] = placedX(p, polygon[2 * k], polygon[2 * k + 1]);
        xy[at + 1] = placedY(p, polygon[2 * k], polygon[2 * k + 1]);
    }

    /** The point (x, y) of a body placed at {@code p}: x, computed as {@link Outlines#place} computes it. */
    private static double placedX(RsTransform p, double x, double y) {
        return p.m11 * x + p.m12 * y + p.m13;
    }

    /** The point (x, y) of a body placed at {@code p}: y, computed as {@link Outlines#place} computes it. */
    private static double placedY(RsTransform p, double x, double y) {
        return p.m21 * x + p.m22 * y + p.m23;
    }

    /** The room a separating line must leave on each side, metres (see the class comment). */
    private double margin(RsTransform pa, RsTransform pb) {
        // An edge is no longer than twice its polygons' reach.
        return MARGIN + Math.sqrt(MARGIN_SQUARED * size(pa, pb) * 2.0 * (reachA + reachB));
    }

    /** How large the placed coordinates can be, metres. */
    private double size(RsTransform pa, RsTransform pb) {
        return Math.max(Math.max(Math.abs(pa.m13), Math.abs(pa.m23)), Math.max(Math.abs(pb.m13), Math.abs(pb.m23)))
                + reachA + reachB;
    }
}
