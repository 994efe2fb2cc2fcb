package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsTransform;

/**
 * The robot-against-robot geometry skips what cannot change its answer (edges and vertices too far
 * away to matter): the distance and the overlap test must still be bit for bit what trying every
 * vertex against every edge gives, since contact times, and so every transcript, are computed from them.
 */
class OutlinesTest {
    private static final int PAIRS = 20_000;

    @Test
    void distanceIsExactlyTheMinimumOverEveryVertexAndEdge() {
        double[][] robot = outlines(roundRobot());
        double[][] box = outlines(boxRobot());
        Random random = new Random(11);
        // Placed anew at every pair, as a robot's outlines are at every sample.
        Outlines reusedRobot = Outlines.at(robot, new RsTransform());
        Outlines reusedBox = Outlines.at(box, new RsTransform());
        int overlapping = 0;
        int within = 0;
        for (int i = 0; i < PAIRS; i++) {
            double[][] a = i % 3 == 0 ? box : robot;
            double[][] b = i % 5 == 0 ? box : robot;
            RsTransform pa = new RsTransform(angle(random), 40 * random.nextDouble(), 40 * random.nextDouble());
            double d = 0.15 + 0.2 * random.nextDouble();
            if (i % 7 == 0) {
                d = 0.2 + 1e-9 * random.nextDouble();
            } else if (i % 11 == 0) {
                d = 0.2 + 0.006 * random.nextDouble();
            }
            double heading = angle(random);
            RsTransform pb = new RsTransform(angle(random), pa.m13 + d * Math.cos(heading), pa.m23 + d * Math.sin(heading));
            Outlines oa = Outlines.at(a, pa);
            Outlines ob = Outlines.at(b, pb);
            boolean overlap = bruteOverlap(a, pa, b, pb);
            overlapping += overlap ? 1 : 0;
            assertEquals(overlap, oa.overlaps(ob), "overlap of pair " + i);
            double expected = overlap ? 0.0 : Math.sqrt(bruteSquaredDistance(a, pa, b, pb));
            assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(oa.distance(ob)), "distance of pair " + i);
            Outlines ra = (a == box ? reusedBox : reusedRobot).place(pa);
            Outlines rb = b == a ? Outlines.at(b, pb) : (b == box ? reusedBox : reusedRobot).place(pb);
            assertEquals(overlap, ra.overlaps(rb), "overlap of pair " + i + ", placed anew");
            for (double limit : new double[] {1e-3, 5e-3, 0.05}) {
                double bounded = ra.distance(rb, limit);
                if (expected <= limit) {
                    within++;
                    assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(bounded),
                            "distance within " + limit + " of pair " + i);
                } else {
                    assertTrue(bounded > limit, "beyond " + limit + " for pair " + i + ": " + bounded);
                }
                // Read against 0 and the limit, as the contact search reads it, the same answer.
                double near = ra.within(rb, limit);
                assertEquals(expected == 0.0, near == 0.0, "touching, within " + limit + ", pair " + i);
                assertEquals(expected <= limit, near <= limit, "near, within " + limit + ", pair " + i);
            }
        }
        assertTrue(overlapping > PAIRS / 10 && overlapping < PAIRS * 9 / 10, "both cases are tried: " + overlapping);
        assertTrue(within > 3 * overlapping + PAIRS / 50, "distances within the limits are tried: " + within);
    }

    private static double angle(Random random) {
        return 2 * Math.PI * random.nextDouble();
    }

    /** The scale arena's wanderer: a round body with a range sensor and a bumper standing out in front. */
    static RsBody roundRobot() {
        RsBody body = new RsBody("round");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
        body.addPart(new RsBodyRangeSensor(new double[] {0.08, -0.01, 0.1, -0.01, 0.1, 0.01, 0.08, 0.01}, 4, 0.1, 0.0,
                0.0, 0.5, 1));
        body.addPart(new RsBodyContactSensor(new double[] {0.09, -0.05, 0.105, -0.05, 0.105, 0.05, 0.09, 0.05}, 4));
        return body;
    }

    static RsBody boxRobot() {
        RsBody body = new RsBody("box");
        body.addPart(new RsBodyShape(new double[] {-0.1, -0.08, 0.12, -0.08, 0.12, 0.08, -0.1, 0.08}, 4));
        return body;
    }

    private static double[][] outlines(RsBody body) {
        RsBodyShape[] shapes = body.getInteractiveBodyShapeArray();
        double[][] outlines = new double[shapes.length][];
        for (int i = 0; i < shapes.length; i++) {
            outlines[i] = shapes[i].getOutlineVertices();
        }
        return outlines;
    }

    private static double[] placed(double[] xy, RsTransform p) {
        double[] out = new double[xy.length];
        for (int k = 0; k < xy.length; k += 2) {
            out[k] = p.m11 * xy[k] + p.m12 * xy[k + 1] + p.m13;
            out[k + 1] = p.m21 * xy[k] + p.m22 * xy[k + 1] + p.m23;
        }
        return out;
    }

    /** Any edge of any polygon of a touching any edge of b, or a first vertex inside the other polygon. */
    private static boolean bruteOverlap(double[][] a, RsTransform pa, double[][] b, RsTransform pb) {
        for (double[] polygonA : a) {
            double[] p = placed(polygonA, pa);
            for (double[] polygonB : b) {
                double[] q = placed(polygonB, pb);
                if (edgesTouch(p, q) || inside(q, p[0], p[1]) || inside(p, q[0], q[1])) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean edgesTouch(double[] p, double[] q) {
        int n = p.length;
        int m = q.length;
        for (int i = 0; i < n; i += 2) {
            for (int j = 0; j < m; j += 2) {
                if (Outlines.segmentsTouch(p[i], p[i + 1], p[(i + 2) % n], p[(i + 3) % n], q[j], q[j + 1], q[(j + 2) % m],
                        q[(j + 3) % m])) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean inside(double[] xy, double px, double py) {
        double[] x = new double[xy.length / 2];
        double[] y = new double[xy.length / 2];
        for (int k = 0; k < x.length; k++) {
            x[k] = xy[2 * k];
            y[k] = xy[2 * k + 1];
        }
        return Outlines.contains(x, y, px, py);
    }

    private static double bruteSquaredDistance(double[][] a, RsTransform pa, double[][] b, RsTransform pb) {
        double best = Double.POSITIVE_INFINITY;
        for (double[] polygonA : a) {
            double[] p = placed(polygonA, pa);
            for (double[] polygonB : b) {
                double[] q = placed(polygonB, pb);
                best = Math.min(best, Math.min(verticesToEdges(p, q), verticesToEdges(q, p)));
            }
        }
        return best;
    }

    private static double verticesToEdges(double[] p, double[] e) {
        double best = Double.POSITIVE_INFINITY;
        int n = e.length;
        for (int k = 0; k < p.length; k += 2) {
            for (int i = 0; i < n; i += 2) {
                best = Math.min(best, Outlines.squaredToSegment(p[k], p[k + 1], e[i], e[i + 1], e[(i + 2) % n], e[(i + 3) % n]));
            }
        }
        return best;
    }
}
