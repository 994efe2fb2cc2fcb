package rp1.simulator.world;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsTransform;

/**
 * Where a robot's range and target sensors can look (docs/behavior.md sections 8.2 and 8.3): each
 * range sensor along one ray, each target sensor anywhere within its range. It decides which other
 * robots a reading could depend on, so that a robot in a crowd turns only those into obstacles.
 */
final class Sight implements RobotIndex.Reach {
    /** Numbers per range sensor in {@link #rays}, and per ray's ends in {@link #placed}. */
    private static final int RAY = 4;
    /** Numbers per target sensor in {@link #fields}. */
    private static final int FIELD = 3;
    /** Numbers per target sensor's centre in {@link #placed}. */
    private static final int CENTRE = 2;
    /**
     * How far {@link #box} reaches beyond the rays and fields, metres: far above the rounding between
     * this class's rays and the sensors' own, and above the slack of {@link #mightSee}'s callers.
     */
    static final double BOX_MARGIN = 1.0e-6;

    /**
     * Per range sensor: detector x, detector y, and the ray from it to its maximum range in body
     * coordinates (maximum range times the sight angle's cosine and sine), one after another.
     */
    private final double[] rays;
    /** Per target sensor: detector x, detector y, maximum range, one after another. */
    private final double[] fields;
    private final double reach;
    /**
     * At the pose last aimed at: the box of {@link #box} (x0, y0, x1, y1), then each ray's ends (x0,
     * y0, x1, y1), then each field's centre (x, y). One array: with ten thousand robots, each object a
     * robot's step reads is a wait for memory, and the rays, their ends and the box were eight of them.
     */
    private final double[] placed;
    private final LastPose at = new LastPose();

    Sight(RsBody body) {
        int nRays = 0;
        int nFields = 0;
        for (RsBodySensor s : body.getBodySensorArray()) {
            nRays += s instanceof RsBodyRangeSensor ? 1 : 0;
            nFields += s instanceof RsBodyTargetSensor ? 1 : 0;
        }
        rays = new double[RAY * nRays];
        fields = new double[FIELD * nFields];
        double max = 0.0;
        int r = 0;
        int f = 0;
        for (RsBodySensor s : body.getBodySensorArray()) {
            if (s instanceof RsBodyRangeSensor) {
                RsBodyRangeSensor g = (RsBodyRangeSensor) s;
                double angle = g.getSightAngle();
                double range = g.getMaxRange();
                rays[r++] = g.getXDetector();
                rays[r++] = g.getYDetector();
                rays[r++] = range * Math.cos(angle);
                rays[r++] = range * Math.sin(angle);
                max = Math.max(max, Math.hypot(g.getXDetector(), g.getYDetector()) + g.getMaxRange());
            } else if (s instanceof RsBodyTargetSensor) {
                RsBodyTargetSensor t = (RsBodyTargetSensor) s;
                fields[f++] = t.getXDetector();
                fields[f++] = t.getYDetector();
                fields[f++] = t.getMaxRange();
                max = Math.max(max, Math.hypot(t.getXDetector(), t.getYDetector()) + t.getMaxRange());
            }
        }
        reach = max;
        placed = new double[centres() + CENTRE * nFields];
    }

    /** Where the fields' centres start in {@link #placed}: after the box and the rays' ends. */
    private int centres() {
        return 4 + rays.length;
    }

    /** How far from the body origin the sensors reach, metres (0 without any). */
    double reach() {
        return reach;
    }

    /**
     * Whether, with the robot at {@code pose}, a reading could depend on something within
     * {@code radius} of (x, y): its ray passes that close, or it lies within a target sensor's range.
     */
    boolean mightSee(RsTransform pose, double x, double y, double radius) {
        return aimedAt(pose).within(x, y, radius);
    }

    /**
     * This sight with the robot at {@code pose}: as a {@link RobotIndex.Reach}, whether a reading could
     * depend on something within a radius of a point, until it is aimed elsewhere.
     */
    Sight aimedAt(RsTransform pose) {
        aim(pose);
        return this;
    }

    /** {@link #mightSee} at the pose last aimed at. */
    @Override
    public boolean within(double x, double y, double radius) {
        double[] p = placed;
        int centres = centres();
        for (int at = 4; at < centres; at += RAY) {
            if (Outlines.squaredToSegment(x, y, p[at], p[at + 1], p[at + 2], p[at + 3]) <= radius * radius) {
                return true;
            }
        }
        for (int from = 0, at = centres; from < fields.length; from += FIELD, at += CENTRE) {
            double dx = p[at];
            double dy = p[at + 1];
            double limit = fields[from + 2] + radius;
            if ((x - dx) * (x - dx) + (y - dy) * (y - dy) <= limit * limit) {
                return true;
            }
        }
        return false;
    }

    /**
     * The box, with the robot at {@code pose}, of all its sensors could look at: each ray from end to
     * end and each target sensor's disc, grown by {@link #BOX_MARGIN}. Walls and robots wholly outside it
     * can neither block a ray nor hide a target. The box is the array's first four numbers (x0, y0, x1,
     * y1); the array is valid until the next call.
     */
    double[] box(RsTransform pose) {
        aim(pose);
        return placed;
    }

    /**
     * Places the rays, fields and box at {@code pose}, unless they already are: a robot's sensors are
     * asked about every robot near it at the same pose. A ray is turned by the pose's matrix, not by its
     * angle: an arc tangent, a sine and a cosine per ray cost more than the rest of the step's sensing
     * in a sweep's quickly compiled code, and the ends differ from the angle's by rounding, far below
     * {@link #BOX_MARGIN}.
     */
    private void aim(RsTransform pose) {
        if (at.is(pose)) {
            return;
        }
        double[] p = placed;
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int from = 0, at = 4; from < rays.length; from += RAY, at += RAY) {
            double rx0 = pose.m11 * rays[from] + pose.m12 * rays[from + 1] + pose.m13;
            double ry0 = pose.m21 * rays[from] + pose.m22 * rays[from + 1] + pose.m23;
            double rx1 = rx0 + pose.m11 * rays[from + 2] + pose.m12 * rays[from + 3];
            double ry1 = ry0 + pose.m21 * rays[from + 2] + pose.m22 * rays[from + 3];
            p[at] = rx0;
            p[at + 1] = ry0;
            p[at + 2] = rx1;
            p[at + 3] = ry1;
            x0 = Math.min(x0, Math.min(rx0, rx1));
            y0 = Math.min(y0, Math.min(ry0, ry1));
            x1 = Math.max(x1, Math.max(rx0, rx1));
            y1 = Math.max(y1, Math.max(ry0, ry1));
        }
        for (int from = 0, at = centres(); from < fields.length; from += FIELD, at += CENTRE) {
            double fx = pose.m11 * fields[from] + pose.m12 * fields[from + 1] + pose.m13;
            double fy = pose.m21 * fields[from] + pose.m22 * fields[from + 1] + pose.m23;
            double r = fields[from + 2];
            p[at] = fx;
            p[at + 1] = fy;
            x0 = Math.min(x0, fx - r);
            y0 = Math.min(y0, fy - r);
            x1 = Math.max(x1, fx + r);
            y1 = Math.max(y1, fy + r);
        }
        p[0] = x0 - BOX_MARGIN;
        p[1] = y0 - BOX_MARGIN;
        p[2] = x1 + BOX_MARGIN;
        p[3] = y1 + BOX_MARGIN;
        at.set(pose);
    }
}
