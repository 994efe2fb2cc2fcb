package rp1demo.ackerman;

import java.util.Locale;
import java.util.function.Consumer;

import rp1demo.navigation.Pose;

/**
 * Steers a car-like robot along a course given as a polyline, by pure pursuit: it aims at the point
 * of the course a fixed distance ahead of where the car is and sets the steering angle of the
 * circle through that point, within the car's steering limit. Progress along the course only ever
 * increases, so a course may cross itself or end where it began.
 */
public final class CourseDriver {
    /** The course is done when less than this is left of it, metres. */
    public static final double FINISH = 0.15;

    /**
     * A command for the car.
     *
     * @param speed metres per second
     * @param angle central steering angle, radians, positive to the left
     */
    public record Steering(double speed, double angle) {
    }

    private final double[] xs;
    private final double[] ys;
    private final double[] along;
    private final double wheelBase;
    private final double lookahead;
    private final double speed;
    private final double maxAngle;
    private final Consumer<String> report;
    private double progress;
    private int passed;
    private volatile boolean finished;

    /**
     * @param course    x0, y0, x1, y1, ...: the course's corners in order, metres (at least two)
     * @param wheelBase distance from the rear axle (the pose's point) to the front axle, metres
     * @param lookahead how far ahead along the course to aim, metres
     * @param speed     driving speed, metres per second
     * @param maxAngle  steering limit, radians
     * @param report    where to tell what the driver does, one line at a time
     */
    public CourseDriver(double[] course, double wheelBase, double lookahead, double speed, double maxAngle,
                        Consumer<String> report) {
        if (course.length < 4 || course.length % 2 != 0) {
            throw new IllegalArgumentException("course needs at least two x, y pairs, got " + course.length + " numbers");
        }
        int n = course.length / 2;
        xs = new double[n];
        ys = new double[n];
        along = new double[n];
        for (int i = 0; i < n; i++) {
            xs[i] = course[2 * i];
            ys[i] = course[2 * i + 1];
            along[i] = i == 0 ? 0.0 : along[i - 1] + Math.hypot(xs[i] - xs[i - 1], ys[i] - ys[i - 1]);
        }
        this.wheelBase = wheelBase;
        this.lookahead = lookahead;
        this.speed = speed;
        this.maxAngle = maxAngle;
        this.report = report;
    }

    /** Length of the course, metres. */
    public double length() {
        return along[along.length - 1];
    }

    /** How far along the course the car has come, metres. */
    public double progress() {
        return progress;
    }

    public boolean isFinished() {
        return finished;
    }

    /** The command for a car whose rear axle is at {@code pose}; null once the course is done. */
    public Steering steer(Pose pose) {
        if (finished) {
            return null;
        }
        progress = nearestAlong(pose, progress, progress + 2.0 * lookahead);
        reportCorners();
        if (length() - progress < FINISH) {
            finished = true;
            report.accept(String.format(Locale.ROOT, "Course complete (%.1f m) at %s", length(), pose));
            return null;
        }
        double[] aim = pointAt(Math.min(progress + lookahead, length()));
        double alpha = pose.turnTowards(aim[0], aim[1]);
        double distance = Math.max(pose.distanceTo(aim[0], aim[1]), 1e-6);
        double angle = Math.atan(2.0 * wheelBase * Math.sin(alpha) / distance);
        return new Steering(speed, Math.max(-maxAngle, Math.min(maxAngle, angle)));
    }

    private void reportCorners() {
        while (passed + 1 < xs.length - 1 && progress >= along[passed + 1]) {
            passed++;
            report.accept(String.format(Locale.ROOT, "Passing corner %d of %d at (%.1f, %.1f)",
                    passed, xs.length - 2, xs[passed], ys[passed]));
        }
    }

    /** The distance along the course, between {@code from} and {@code to}, of the course point nearest the pose. */
    private double nearestAlong(Pose pose, double from, double to) {
        double best = from;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (int i = 0; i + 1 < xs.length; i++) {
            if (along[i + 1] < from || along[i] > to) {
                continue;
            }
            double dx = xs[i + 1] - xs[i];
            double dy = ys[i + 1] - ys[i];
            double len2 = dx * dx + dy * dy;
            double t = len2 == 0.0 ? 0.0 : ((pose.x() - xs[i]) * dx + (pose.y() - ys[i]) * dy) / len2;
            double s = Math.max(from, Math.min(to, along[i] + Math.max(0.0, Math.min(1.0, t)) * Math.sqrt(len2)));
            double[] p = pointAt(s);
            double d = pose.distanceTo(p[0], p[1]);
            if (d < bestDistance) {
                bestDistance = d;
                best = s;
            }
        }
        return best;
    }

    /** The course point {@code s} metres from its start. */
    private double[] pointAt(double s) {
        for (int i = 0; i + 1 < xs.length; i++) {
            if (s <= along[i + 1] || i + 2 == xs.length) {
                double len = along[i + 1] - along[i];
                double t = len == 0.0 ? 0.0 : Math.max(0.0, Math.min(1.0, (s - along[i]) / len));
                return new double[] {xs[i] + t * (xs[i + 1] - xs[i]), ys[i] + t * (ys[i + 1] - ys[i])};
            }
        }
        return new double[] {xs[0], ys[0]};
    }
}
