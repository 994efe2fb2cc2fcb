package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsSegSect;
import rp1.rossum.RsSegment;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;

/**
 * A robot's interactive shapes (the parts that collide) in body coordinates, with what the world needs
 * from them: their outlines at a pose as wall polygons (so other robots' sensors and collision
 * searches see this robot), overlap with another robot, and how far from the body origin they reach.
 */
final class RobotShapes {
    private final double[][] outlines;
    private final double reach;
    /** The last pose {@link #asWalls} was asked for (m11, m12, m13, m21, m22, m23) and its answer. */
    private final double[] wallsPose = new double[6];
    private RsWall[] walls;

    RobotShapes(RsBody body) {
        RsBodyShape[] shapes = body.getInteractiveBodyShapeArray();
        outlines = new double[shapes.length][];
        double r = 0.0;
        for (int i = 0; i < shapes.length; i++) {
            outlines[i] = shapes[i].getOutlineVertices();
            for (int k = 0; k + 1 < outlines[i].length; k += 2) {
                r = Math.max(r, Math.hypot(outlines[i][k], outlines[i][k + 1]));
            }
        }
        reach = r;
    }

    /** The largest distance of any outline vertex from the body origin, metres. */
    double reach() {
        return reach;
    }

    boolean isEmpty() {
        return outlines.length == 0;
    }

    /**
     * The shapes at {@code pose} as walls named {@code name}; shapes without area are left out. Every
     * robot with a sensor asks for every nearby robot's walls at each motion step, so the answer for
     * the last pose is kept; callers only read it.
     */
    RsWall[] asWalls(RsTransform pose, String name) {
        double[] p = {pose.m11, pose.m12, pose.m13, pose.m21, pose.m22, pose.m23};
        if (walls == null || !Arrays.equals(p, wallsPose)) {
            walls = wallsAt(pose, name);
            System.arraycopy(p, 0, wallsPose, 0, p.length);
        }
        return walls;
    }

    private RsWall[] wallsAt(RsTransform pose, String name) {
        RsWall[] walls = new RsWall[outlines.length];
        int n = 0;
        for (double[] outline : outlines) {
            RsWall w = new RsWall(name, null);
            w.setGeometry(map(outline, pose));
            if (w.isGeometrySet) {
                walls[n++] = w;
            }
        }
        return n == walls.length ? walls : Arrays.copyOf(walls, n);
    }

    /** The shapes' edges at {@code pose}, one array per shape. */
    RsSegment[][] edgesAt(RsTransform pose) {
        RsSegment[][] edges = new RsSegment[outlines.length][];
        for (int i = 0; i < outlines.length; i++) {
            double[] xy = map(outlines[i], pose);
            int n = xy.length / 2;
            edges[i] = new RsSegment[n];
            for (int k = 0; k < n; k++) {
                int j = (k + 1) % n;
                edges[i][k] = new RsSegment(xy[2 * k], xy[2 * k + 1], xy[2 * j], xy[2 * j + 1]);
            }
        }
        return edges;
    }

    /** The bounding box of the shapes at {@code pose}. */
    static RsRectangle bounds(RsSegment[][] edges) {
        RsRectangle r = new RsRectangle();
        for (RsSegment[] shape : edges) {
            for (RsSegment s : shape) {
                r.insert(s.x, s.y);
            }
        }
        return r;
    }

    /** How far the polygon is from the nearest of the shapes, metres; 0 if they overlap. */
    static double distance(RsSegment[] polygon, RsSegment[][] shapes) {
        if (overlap(new RsSegment[][] {polygon}, shapes)) {
            return 0.0;
        }
        double best = Double.POSITIVE_INFINITY;
        for (RsSegment a : polygon) {
            for (RsSegment[] shape : shapes) {
                for (RsSegment b : shape) {
                    best = Math.min(best, Math.min(
                            Math.min(pointToSegment(a.x, a.y, b), pointToSegment(a.x + a.v.x, a.y + a.v.y, b)),
                            Math.min(pointToSegment(b.x, b.y, a), pointToSegment(b.x + b.v.x, b.y + b.v.y, a))));
                }
            }
        }
        return best;
    }

    /** The distance of point (px, py) from segment {@code s}. */
    private static double pointToSegment(double px, double py, RsSegment s) {
        double len2 = s.v.x * s.v.x + s.v.y * s.v.y;
        double u = len2 == 0.0 ? 0.0 : Math.max(0.0, Math.min(1.0, ((px - s.x) * s.v.x + (py - s.y) * s.v.y) / len2));
        return Math.hypot(px - (s.x + u * s.v.x), py - (s.y + u * s.v.y));
    }

    /** Whether two sets of shapes touch: an edge of one crosses an edge of the other, or one holds a vertex of the other. */
    static boolean overlap(RsSegment[][] a, RsSegment[][] b) {
        RsSegSect sect = new RsSegSect();
        for (RsSegment[] pa : a) {
            for (RsSegment[] pb : b) {
                if (edgesCross(pa, pb, sect) || contains(pa, pb[0]) || contains(pb, pa[0])) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean edgesCross(RsSegment[] a, RsSegment[] b, RsSegSect sect) {
        for (RsSegment ea : a) {
            for (RsSegment eb : b) {
                if (sect.process(ea, eb)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Even-odd containment of a point (the start of segment {@code p}) in a closed polygon; each edge
     * ends where the next begins, so a vertex on the ray is counted consistently.
     */
    private static boolean contains(RsSegment[] polygon, RsSegment p) {
        if (polygon.length < 3) {
            return false;
        }
        boolean inside = false;
        for (int i = 0; i < polygon.length; i++) {
            RsSegment e = polygon[i];
            RsSegment next = polygon[(i + 1) % polygon.length];
            double y0 = e.y;
            double y1 = next.y;
            if ((y0 > p.y) != (y1 > p.y) && p.x < e.x + (p.y - y0) / (y1 - y0) * (next.x - e.x)) {
                inside = !inside;
            }
        }
        return inside;
    }

    private static double[] map(double[] outline, RsTransform pose) {
        double[] xy = new double[outline.length];
        for (int k = 0; k + 1 < outline.length; k += 2) {
            double x = outline[k];
            double y = outline[k + 1];
            xy[k] = pose.m11 * x + pose.m12 * y + pose.m13;
            xy[k + 1] = pose.m21 * x + pose.m22 * y + pose.m23;
        }
        return xy;
    }
}
