package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;

/**
 * A robot's interactive shapes (the parts that collide) in body coordinates, with what the world needs
 * from them: their outlines at a pose as wall polygons (so other robots' sensors see this robot and
 * placements keep clear of it), their outlines to place for the robot-against-robot tests
 * ({@link PlacedOutlines}), and how far from the body origin they reach.
 */
final class RobotShapes {
    private final double[][] outlines;
    private final Hull[] hulls;
    private final double reach;
    /** The last pose {@link #asWalls} was asked for, and its answer. */
    private final LastPose wallsPose = new LastPose();
    private RsWall[] walls;
    private final ContactSensors contactSensors;

    /** The body's shapes, their outlines shared through {@code sources} with every robot of the same design. */
    RobotShapes(RsBody body, OutlineSources sources) {
        contactSensors = new ContactSensors(body, sources);
        RsBodyShape[] shapes = body.getInteractiveBodyShapeArray();
        double[][] own = new double[shapes.length][];
        double r = 0.0;
        for (int i = 0; i < shapes.length; i++) {
            own[i] = shapes[i].getOutlineVertices();
            r = Math.max(r, farthest(own[i]));
        }
        outlines = sources.intern(own);
        hulls = sources.hulls(outlines);
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
        if (walls == null || !wallsPose.is(pose)) {
            walls = wallsAt(pose, name);
            wallsPose.set(pose);
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

    /**
     * The shapes' outlines (each x0, y0, x1, y1, ... in body coordinates), to place with {@link Outlines}:
     * shared with the robots of the same design, and only read.
     */
    double[][] outlines() {
        return outlines;
    }

    /** The convex hull of each polygon of {@link #outlines()}, shared like them; only read. */
    Hull[] hulls() {
        return hulls;
    }

    /** The body's contact sensors, in the body's order, with their outlines ready to place. */
    ContactSensors contactSensors() {
        return contactSensors;
    }

    /**
     * A body's contact sensors and the outline of each, to place at a pose: which of them touch another
     * robot is asked at every contact between robots.
     */
    static final class ContactSensors {
        private final RsBodyContactSensor[] sensors;
        /** Each sensor's outline as outlines of one polygon, shared like the shapes' outlines. */
        private final double[][][] outlines;
        /** Each sensor's hull, as the hulls of its outline. */
        private final Hull[][] hulls;
        /** The largest distance of any sensor outline's vertex from the body origin, metres. */
        private final double reach;

        private ContactSensors(RsBody body, OutlineSources sources) {
            int n = 0;
            RsBodySensor[] all = body.getBodySensorArray();
            RsBodyContactSensor[] found = new RsBodyContactSensor[all.length];
            for (RsBodySensor s : all) {
                if (s instanceof RsBodyContactSensor) {
                    found[n++] = (RsBodyContactSensor) s;
                }
            }
            sensors = Arrays.copyOf(found, n);
            outlines = new double[n][][];
            hulls = new Hull[n][];
            double r = 0.0;
            for (int i = 0; i < n; i++) {
                double[] outline = sensors[i].getOutlineVertices();
                outlines[i] = sources.intern(new double[][] {outline});
                hulls[i] = sources.hulls(outlines[i]);
                r = Math.max(r, farthest(outline));
            }
            reach = r;
        }

        /** The largest distance of any sensor outline's vertex from the body origin, metres. */
        double reach() {
            return reach;
        }

        int count() {
            return sensors.length;
        }

        RsBodyContactSensor sensor(int i) {
            return sensors[i];
        }

        /** Sensor {@code i}'s outline as outlines of one polygon (body coordinates), to place with {@link Outlines}. */
        double[][] outline(int i) {
            return outlines[i];
        }

        /** Sensor {@code i}'s hull (body coordinates) as the hulls of {@link #outline}, shared like it. */
        Hull[] hulls(int i) {
            return hulls[i];
        }
    }

    /** How far the farthest vertex of {@code outline} (x0, y0, x1, y1, ...) is from the body origin, metres. */
    private static double farthest(double[] outline) {
        double r = 0.0;
        for (int k = 0; k + 1 < outline.length; k += 2) {
            r = Math.max(r, Math.hypot(outline[k], outline[k + 1]));
        }
        return r;
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
