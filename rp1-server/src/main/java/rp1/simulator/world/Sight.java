package rp1.simulator.world;

import java.util.ArrayList;
import java.util.List;

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
    /**
     * Per range sensor: detector x, detector y, and the ray from it to its maximum range in body
     * coordinates (maximum range times the sight angle's cosine and sine).
     */
    private final double[][] rays;
    /** Per target sensor: detector x, detector y, maximum range. */
    private final double[][] fields;
    private final double reach;
    /**
     * How far {@link #box} reaches beyond the rays and fields, metres: far above the rounding between
     * this class's rays and the sensors' own, and above the slack of {@link #mightSee}'s callers.
     */
    static final double BOX_MARGIN = 1.0e-6;
    /** The rays' ends and the fields' centres at the pose {@link #at} (once {@link #aimed}). */
    private final double[] rayX0;
    private final double[] rayY0;
    private final double[] rayX1;
    private final double[] rayY1;
    private final double[] fieldX;
    private final double[] fieldY;
    private final LastPose at = new LastPose();
    private boolean aimed;
    /** The box of {@link #box}: x0, y0, x1, y1 at the pose {@link #at}. */
    private final double[] box = new double[4];

    Sight(RsBody body) {
        List<double[]> r = new ArrayList<>();
        List<double[]> f = new ArrayList<>();
        double max = 0.0;
        for (RsBodySensor s : body.getBodySensorArray()) {
            if (s instanceof RsBodyRangeSensor) {
                RsBodyRangeSensor g = (RsBodyRangeSensor) s;
                double angle = g.getSightAngle();
                double range = g.getMaxRange();
                r.add(new double[] {g.getXDetector(), g.getYDetector(), range * Math.cos(angle), range * Math.sin(angle)});
                max = Math.max(max, Math.hypot(g.getXDetector(), g.getYDetector()) + g.getMaxRange());
            } else if (s instanceof RsBodyTargetSensor) {
                RsBodyTargetSensor t = (RsBodyTargetSensor) s;
                f.add(new double[] {t.getXDetector(), t.getYDetector(), t.getMaxRange()});
                max = Math.max(max, Math.hypot(t.getXDetector(), t.getYDetector()) + t.getMaxRange());
            }
        }
        rays = r.toArray(new double[0][]);
        fields = f.toArray(new double[0][]);
        reach = max;
        rayX0 = new double[rays.length];
        rayY0 = new double[rays.length];
        rayX1 = new double[rays.length];
        rayY1 = new double[rays.length];
        fieldX = new double[fields.length];
        fieldY = new double[fields.length];
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
        for (int i = 0; i < rays.length; i++) {
            if (Outlines.squaredToSegment(x, y, rayX0[i], rayY0[i], rayX1[i], rayY1[i]) <= radius * radius) {
                return true;
            }
        }
        for (int i = 0; i < fields.length; i++) {
            double dx = fieldX[i];
            double dy = fieldY[i];
            double limit = fields[i][2] + radius;
            if ((x - dx) * (x - dx) + (y - dy) * (y - dy) <= limit * limit) {
                return true;
            }
        }
        return false;
    }

    /**
     * The box, with the robot at {@code pose}, of all its sensors could look at: each ray from end to
     * end and each target sensor's disc, grown by {@link #BOX_MARGIN}. Walls and robots wholly outside it
     * can neither block a ray nor hide a target. One array, valid until the next call.
     */
    double[] box(RsTransform pose) {
        aim(pose);
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < rays.length; i++) {
            x0 = Math.min(x0, Math.min(rayX0[i], rayX1[i]));
            y0 = Math.min(y0, Math.min(rayY0[i], rayY1[i]));
            x1 = Math.max(x1, Math.max(rayX0[i], rayX1[i]));
            y1 = Math.max(y1, Math.max(rayY0[i], rayY1[i]));
        }
        for (int i = 0; i < fields.length; i++) {
            double r = fields[i][2];
            x0 = Math.min(x0, fieldX[i] - r);
            y0 = Math.min(y0, fieldY[i] - r);
            x1 = Math.max(x1, fieldX[i] + r);
            y1 = Math.max(y1, fieldY[i] + r);
        }
        box[0] = x0 - BOX_MARGIN;
        box[1] = y0 - BOX_MARGIN;
        box[2] = x1 + BOX_MARGIN;
        box[3] = y1 + BOX_MARGIN;
        return box;
    }

    /**
     * Places the rays and fields at {@code pose}, unless they already are: a robot's sensors are asked
     * about every robot near it at the same pose. A ray is turned by the pose's matrix, not by its
     * angle: an arc tangent, a sine and a cosine per ray cost more than the rest of the step's sensing
     * in a sweep's quickly compiled code, and the ends differ from the angle's by rounding, far below
     * {@link #BOX_MARGIN}.
     */
    private void aim(RsTransform pose) {
        if (aimed && at.is(pose)) {
            return;
        }
        for (int i = 0; i < rays.length; i++) {
            double[] ray = rays[i];
            rayX0[i] = pose.m11 * ray[0] + pose.m12 * ray[1] + pose.m13;
            rayY0[i] = pose.m21 * ray[0] + pose.m22 * ray[1] + pose.m23;
            rayX1[i] = rayX0[i] + pose.m11 * ray[2] + pose.m12 * ray[3];
            rayY1[i] = rayY0[i] + pose.m21 * ray[2] + pose.m22 * ray[3];
        }
        for (int i = 0; i < fields.length; i++) {
            double[] field = fields[i];
            fieldX[i] = pose.m11 * field[0] + pose.m12 * field[1] + pose.m13;
            fieldY[i] = pose.m21 * field[0] + pose.m22 * field[1] + pose.m23;
        }
        at.set(pose);
        aimed = true;
    }
}
