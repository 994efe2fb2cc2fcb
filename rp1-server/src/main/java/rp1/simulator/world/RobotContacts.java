package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsMotion;
import rp1.rossum.RsTransform;

/**
 * Robots meeting robots (beyond RP1 0.60, where robots passed through each other). Walls are known in
 * advance, so a motion is cut before the first wall analytically when it starts; other robots move,
 * so at every motion step the coming interval is searched for the first time two robots touch. Only
 * pairs that can meet in the interval are looked at ({@link Surroundings}). Both poses are analytic:
 * while two robots are far apart the search advances by the time they need at least to close the gap
 * (their distance over their speeds), then samples finely enough that neither body can pass through
 * the other between samples (robots are bodies of at least a few centimetres), then narrows the
 * contact down by bisection. Each robot that was moving stops at the last whole millisecond before
 * contact, its motion marked as ended by collision; the contact sensors of either robot that touch the
 * other at the moment of contact go hot with its name.
 *
 * <p>It keeps, by robot number, in which run of the motion task each robot's motion started and it
 * last searched, to search each pair of moving robots once.
 */
final class RobotContacts {
    /** Largest relative displacement between samples, metres. */
    static final double SAMPLE_SPACING = 0.005;
    /**
     * How far past the next evaluation the search looks, seconds: a contact just after it would
     * otherwise be found one step late, when the robot can no longer stop a millisecond before it.
     */
    static final double LOOK_AHEAD = 0.002;
    /**
     * Slack, relative to the size of the coordinates, of the test that two robots' reach circles keep
     * apart: far more than the rounding of a pose, so that outlines which could touch are always tested.
     */
    private static final double CIRCLES_SLACK = 1.0e-9;
    /** The contact time is narrowed down to this, seconds. */
    private static final double PRECISION = 1.0e-5;
    /**
     * A contact sensor touches the other robot if it is this close to it at the moment of contact,
     * metres: robots meeting face to face touch along parallel edges, where an exact test is at the
     * mercy of rounding.
     */
    private static final double TOUCHING = 1.0e-3;
    /**
     * Added to how far a sensor's distance can change over a narrowed interval before it counts as
     * settled, metres: far above the rounding of poses and distances.
     */
    private static final double SETTLED_SLACK = 1.0e-9;

    private final Surroundings surroundings;
    /** By robot number: the motion task's run in which the robot's current motion started (-1: none). */
    private long[] startedIn = new long[0];
    /** By robot number: the motion task's run in which the robot last searched for contacts (-1: never). */
    private long[] searchedIn = new long[0];
    private final Touches touches = new Touches();
    /** The outlines of the pair being searched, and of contact sensors, placed. */
    private final PlacedOutlines placed = new PlacedOutlines();
    /** Settles most samples of robots pressed together without placing their outlines. */
    private final SeparatingAxes axes = new SeparatingAxes();
    /**
     * The poses of the pair at the time being looked at, written anew at each look (nothing keeps
     * them: placed outlines remember a pose by copying it). A new pose for each of the two robots at
     * every sample was a third of what a crowd allocated.
     */
    private final RsTransform poseA = new RsTransform();
    private final RsTransform poseB = new RsTransform();

    RobotContacts(Surroundings surroundings) {
        this.surroundings = surroundings;
    }

    /** The robot's motion started in the motion task's run {@code run}. */
    void motionStarted(Robot r, long run) {
        int n = room(r);
        startedIn[n] = run;
    }

    /**
     * Presses the robot's contact sensors that robots which ran into it while it stood still touch, if
     * their time has come by {@code time}.
     *
     * @return the earliest time sensors still wait to be pressed at, or NaN if none wait
     */
    double pressTouched(Robot r, double time) {
        return touches.press(r, time);
    }

    /**
     * The robot's number, once the bookkeeping has room for it (call it before reading the arrays,
     * which it may replace).
     */
    private int room(Robot r) {
        int n = r.getNumber();
        if (n >= startedIn.length) {
            int length = Math.max(n + 1, 2 * startedIn.length);
            int old = startedIn.length;
            startedIn = Arrays.copyOf(startedIn, length);
            searchedIn = Arrays.copyOf(searchedIn, length);
            Arrays.fill(startedIn, old, length, -1L);
            Arrays.fill(searchedIn, old, length, -1L);
        }
        return n;
    }

    /**
     * Searches [from, to] for contacts between each moving robot of {@code evaluated} (the robots
     * evaluated now, in joining order, their motions started) and the robots near it, pair by pair in
     * joining order. A moving robot is evaluated every interval and searches the interval after each
     * evaluation, so its evaluations cover all the time it moves: a pair of moving robots is searched
     * by the one that joined first, and by the other only if that one's last search could not know
     * the other's current motion (it started in a later run of the motion task: each robot has its own
     * evaluation times). A robot stopped here, or run into while at rest, is due for evaluation when
     * that happens.
     *
     * @param run the motion task's run under way (motions started in it precede every search in it)
     */
    void resolve(List<Robot> evaluated, double from, double to, long run, MotionStepper stepper) {
        for (Robot a : evaluated) {
            if (!a.isMoving() || a.shapes().isEmpty()) {
                continue;
            }
            int n = room(a);
            searchedIn[n] = run;
            double reach = a.shapes().reach() + a.speedBound() * (to - from) + SAMPLE_SPACING;
            RsTransform p = a.poseAt(from, poseA);
            for (Robot b : surroundings.robotsNear(a, p.m13 - reach, p.m23 - reach, p.m13 + reach, p.m23 + reach)) {
                if (coveredBy(b, a)) {
                    continue;
                }
                boolean aFirst = a.getNumber() < b.getNumber();
                resolvePair(aFirst ? a : b, aFirst ? b : a, from, to, stepper);
            }
        }
    }

    /**
     * Whether moving robot {@code b}'s own searches already cover the pair for {@code a} (which is
     * searching, so the bookkeeping has room for it and for {@code b}, numbered before it).
     */
    private boolean coveredBy(Robot b, Robot a) {
        return b.isMoving() && b.getNumber() < a.getNumber() && searchedIn[b.getNumber()] >= startedIn[a.getNumber()];
    }

    private void resolvePair(Robot a, Robot b, double from, double to, MotionStepper stepper) {
        double speed = a.speedBound() + b.speedBound();
        if (speed <= 0.0) {
            return;
        }
        double gap = gap(a, b, from);
        if (gap == 0.0) {
            stop(a, b, from, from, stepper);
            return;
        }
        double clear = from;
        double t = from;
        while (gap > SAMPLE_SPACING) {
            // They cannot touch before closing the gap at their highest speed: jump to then.
            t += gap / speed;
            if (t >= to) {
                return;
            }
            gap = gap(a, b, t);
            if (gap > 0.0) {
                clear = t;
            }
        }
        if (gap == 0.0) {
            narrowAndStop(a, b, clear, t, from, stepper);
            return;
        }
        double step = SAMPLE_SPACING / speed;
        for (t = Math.min(to, clear + step); ; t = Math.min(to, t + step)) {
            if (touch(a, b, t)) {
                narrowAndStop(a, b, clear, t, from, stepper);
                return;
            }
            clear = t;
            if (t >= to) {
                return;
            }
        }
    }

    /**
     * The gap between the two robots' shapes at time {@code t} as the search reads it. Above
     * {@link #SAMPLE_SPACING}, a lower bound of their distance to jump by: the gap between the circles
     * of their reach while that is wide, else the exact distance of their outlines. Within it, only
     * whether they touch: 0 if they do, else {@code SAMPLE_SPACING}.
     */
    private double gap(Robot a, Robot b, double t) {
        RsTransform pa = a.poseAt(t, poseA);
        RsTransform pb = b.poseAt(t, poseB);
        double circles = circlesGap(a, pa, b, pb);
        if (circles > SAMPLE_SPACING) {
            return circles;
        }
        // Within the sampling spacing only whether they touch matters, and the search for a vertex near
        // an edge can end at the first; beyond it the search needs the exact distance to jump by. Robots
        // pressed together are mostly shown touching, or apart and near, without placing their outlines.
        int found = axes.look(a, pa, b, pb);
        if (found == SeparatingAxes.TOUCHING) {
            return 0.0;
        }
        if (found == SeparatingAxes.APART) {
            if (axes.near(pa, pb, SAMPLE_SPACING)) {
                return SAMPLE_SPACING;
            }
            double distance = axes.distance(pa, pb);
            if (!Double.isNaN(distance)) {
                return distance <= SAMPLE_SPACING ? SAMPLE_SPACING : distance;
            }
        }
        Outlines outlinesA = placed.of(a, pa);
        Outlines outlinesB = placed.of(b, pb);
        double near = outlinesA.within(outlinesB, SAMPLE_SPACING);
        return near <= SAMPLE_SPACING ? near : outlinesA.distance(outlinesB);
    }

    /**
     * How far apart the circles of the two robots' reach are at poses {@code pa} and {@code pb}
     * (negative if they overlap): every outline lies within its robot's reach of the body origin.
     */
    private static double circlesGap(Robot a, RsTransform pa, Robot b, RsTransform pb) {
        return Math.hypot(pa.m13 - pb.m13, pa.m23 - pb.m23) - a.shapes().reach() - b.shapes().reach();
    }

    /**
     * Narrows the first touching time in (clear, touching] down by bisection and stops the pair there.
     *
     * <p>Only three things depend on the contact time: each moving robot's stop time (a whole
     * millisecond before it), whether it is before the motion's end, and which contact sensors are
     * within {@link #TOUCHING} of the other robot. The bisection stops as soon as those are the same
     * wherever in the interval the contact lies, which is usually long before the interval is down to
     * {@link #PRECISION}: the stop time can only grow with the contact time, so equal stop times at both
     * ends hold throughout, and a sensor's distance to the other robot changes no faster than their
     * points move, so a distance far enough from {@code TOUCHING} at one end is on the same side
     * throughout. The halvings it does are the same as those of a full bisection, so what it decides is
     * what a full bisection would.
     */
    private void narrowAndStop(Robot a, Robot b, double clear, double touching, double now, MotionStepper stepper) {
        // How fast a sensor's distance to the other robot can change: its points' speed plus the other's.
        double speedA = a.speedBound(a.shapes().contactSensors().reach()) + b.speedBound();
        double speedB = b.speedBound(b.shapes().contactSensors().reach()) + a.speedBound();
        boolean sensorsUnsettled = false;
        while (touching - clear > PRECISION) {
            if (!sensorsUnsettled && sameStop(a, clear, touching, now) && sameStop(b, clear, touching, now)) {
                double width = touching - clear;
                List<RsBodyContactSensor> touchingA = touching(a, b, touching, speedA * width + SETTLED_SLACK);
                List<RsBodyContactSensor> touchingB = touchingA == null
                        ? null : touching(b, a, touching, speedB * width + SETTLED_SLACK);
                if (touchingB != null) {
                    stop(a, b, touching, touchingA, touchingB, now, stepper);
                    return;
                }
                // A sensor at about TOUCHING from the other robot: bisect to the end, as before.
                sensorsUnsettled = true;
            }
            double mid = 0.5 * (clear + touching);
            if (touch(a, b, mid)) {
                touching = mid;
            } else {
                clear = mid;
            }
        }
        stop(a, b, touching, now, stepper);
    }

    /** Whether the robot's stop for a contact at {@code clear} and at {@code touching} is the same. */
    private static boolean sameStop(Robot r, double clear, double touching, double now) {
        return Double.compare(stopTime(r, clear, now), stopTime(r, touching, now)) == 0;
    }

    private boolean touch(Robot a, Robot b, double t) {
        RsTransform pa = a.poseAt(t, poseA);
        RsTransform pb = b.poseAt(t, poseB);
        // Circles that keep apart settle it without building either outline (most samples of a pair
        // closing in).
        if (circlesGap(a, pa, b, pb) > CIRCLES_SLACK * (1.0 + Math.abs(pa.m13) + Math.abs(pa.m23))) {
            return false;
        }
        // Most samples of robots pressed together are settled without placing their outlines.
        int found = axes.look(a, pa, b, pb);
        if (found != SeparatingAxes.UNKNOWN) {
            return found == SeparatingAxes.TOUCHING;
        }
        Outlines outlinesA = placed.of(a, pa);
        return outlinesA.overlaps(placed.of(b, pb));
    }

    /**
     * Stops each moving robot of the pair before {@code contact} (not before {@code now}); the contact
     * sensors of both that touch the other robot go hot with its name: a stopped robot's when its
     * motion ends, a robot at rest's at the time the other one stops.
     */
    private void stop(Robot a, Robot b, double contact, double now, MotionStepper stepper) {
        stop(a, b, contact, touching(a, b, contact, 0.0), touching(b, a, contact, 0.0), now, stepper);
    }

    /** {@link #stop(Robot, Robot, double, double, MotionStepper)} with the touching sensors known. */
    private void stop(Robot a, Robot b, double contact, List<RsBodyContactSensor> touchingA,
                      List<RsBodyContactSensor> touchingB, double now, MotionStepper stepper) {
        double stopA = stopOne(a, contact, now);
        double stopB = stopOne(b, contact, now);
        press(a, b, touchingA, stopA, stopB, stepper);
        press(b, a, touchingB, stopB, stopA, stepper);
    }

    /**
     * When the robot stops for a contact at {@code contact}: the last whole millisecond of its motion
     * before it (not before {@code now}); NaN if it is not moving or its motion ends first. It never
     * decreases as {@code contact} grows (each step of it is monotonic, rounding included).
     */
    private static double stopTime(Robot r, double contact, double now) {
        RsMotion m = r.motion();
        if (!r.isMoving() || m == null) {
            return Double.NaN;
        }
        double stopAt = Math.max(now, m.time0 + RsMotion.stopTimeForContact(contact - m.time0));
        return stopAt >= m.time1 ? Double.NaN : stopAt;
    }

    /**
     * Cuts the robot's motion before the contact; returns the stop time, or NaN if it was not moving into it.
     * The motion's collision time is the contact as far as it was narrowed down.
     */
    private static double stopOne(Robot r, double contact, double now) {
        double stopAt = stopTime(r, contact, now);
        if (Double.isNaN(stopAt)) {
            return Double.NaN;
        }
        RsMotion m = r.motion();
        m.stopMotionAtTime(stopAt);
        m.collision = true;
        m.collisionTime = contact - m.time0;
        r.getBody().setCollision(true);
        return stopAt;
    }

    /**
     * The robot's contact sensors that touch the other robot at time {@code contact} (both motions as
     * requested), or null if one of them is within {@code margin} of touching and not touching by more
     * than that (with a margin of 0, never null).
     */
    private List<RsBodyContactSensor> touching(Robot r, Robot other, double contact, double margin) {
        RobotShapes.ContactSensors sensors = r.shapes().contactSensors();
        if (sensors.count() == 0) {
            return List.of();
        }
        List<RsBodyContactSensor> touching = new ArrayList<>();
        RsTransform otherPose = other.poseAt(contact, poseB);
        Outlines otherShapes = null;
        RsTransform pose = r.poseAt(contact, poseA);
        double reach = Math.max(r.shapes().reach(), sensors.reach());
        for (int i = 0; i < sensors.count(); i++) {
            // Most sensors are shown beyond both limits (a bumper at the front of a robot run into from
            // behind) or touching the other robot from a few vertices.
            int found = axes.lookBeyond(sensors.sensor(i), sensors.hulls(i), sensors.outline(i), reach, pose, other,
                    otherPose, TOUCHING + margin);
            if (found == SeparatingAxes.APART) {
                continue;
            }
            double d = 0.0;
            if (found == SeparatingAxes.UNKNOWN) {
                if (otherShapes == null) {
                    otherShapes = placed.of(other, otherPose);
                }
                // Bit for bit the distance up to the limit, so a margin of 0 is the plain test.
                d = placed.sensor(sensors.outline(i), pose).distance(otherShapes, TOUCHING + margin);
            }
            if (d <= TOUCHING - margin) {
                touching.add(sensors.sensor(i));
            } else if (d <= TOUCHING + margin) {
                return null;
            }
        }
        return touching;
    }

    /**
     * A robot that was stopped has exactly its touching sensors flagged, to go hot when its motion ends;
     * one at rest has them pressed when the other robot has stopped.
     */
    private void press(Robot r, Robot other, List<RsBodyContactSensor> touching, double ownStop, double otherStop,
                              MotionStepper stepper) {
        if (!Double.isNaN(ownStop)) {
            stepper.evaluateBy(r, ownStop);
            for (RsBodySensor s : r.getBody().getBodySensors()) {
                if (s instanceof RsBodyContactSensor) {
                    boolean touches = touching.contains(s);
                    ((RsBodyContactSensor) s).setCollision(touches, touches ? other.getLabel() : null);
                }
            }
        } else if (!touching.isEmpty() && !Double.isNaN(otherStop)) {
            touches.add(r, otherStop, touching, other.getLabel());
            stepper.evaluateBy(r, otherStop);
        }
    }
}
