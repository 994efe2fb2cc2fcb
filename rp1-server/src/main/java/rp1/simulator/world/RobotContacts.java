package rp1.simulator.world;

import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsMotion;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsSegment;
import rp1.rossum.RsTransform;

/**
 * Robots meeting robots (beyond RP1 0.60, where robots passed through each other). Walls are known in
 * advance, so a motion is cut before the first wall analytically when it starts; other robots move,
 * so at every motion step the coming interval is searched for the first time two robots touch. Both
 * poses are analytic, so the search samples the interval finely enough that neither body can pass
 * through the other between samples (robots are bodies of at least a few centimetres), then narrows
 * the contact down by bisection. Each robot that was moving stops at the last whole millisecond
 * before contact, its motion marked as ended by collision; the contact sensors of either robot that
 * touch the other at the moment of contact go hot with its name.
 */
final class RobotContacts {
    /** Largest relative displacement between samples, metres. */
    private static final double SAMPLE_SPACING = 0.005;
    /**
     * How far past the next evaluation the search looks, seconds: a contact just after it would
     * otherwise be found one step late, when the robot can no longer stop a millisecond before it.
     */
    static final double LOOK_AHEAD = 0.002;
    /** The contact time is narrowed down to this, seconds. */
    private static final double PRECISION = 1.0e-5;
    /**
     * A contact sensor touches the other robot if it is this close to it at the moment of contact,
     * metres: robots meeting face to face touch along parallel edges, where an exact test is at the
     * mercy of rounding.
     */
    private static final double TOUCHING = 1.0e-3;

    private RobotContacts() {
    }

    /** Searches [from, to] for contacts between moving robots and every other placed robot. */
    static void resolve(List<Robot> placed, double from, double to) {
        int n = placed.size();
        // Each robot's swept box once, not once per pair: the pair test is then a box overlap.
        RsRectangle[] boxes = new RsRectangle[n];
        for (int i = 0; i < n; i++) {
            Robot r = placed.get(i);
            boxes[i] = r.shapes().isEmpty() ? null : swept(r, from, to);
        }
        for (int i = 0; i < n; i++) {
            Robot a = placed.get(i);
            for (int j = i + 1; j < n; j++) {
                Robot b = placed.get(j);
                if ((a.isMoving() || b.isMoving()) && boxes[i] != null && boxes[j] != null
                        && boxes[i].intersects(boxes[j])) {
                    resolvePair(a, b, from, to);
                }
            }
        }
    }

    private static void resolvePair(Robot a, Robot b, double from, double to) {
        double speed = speedBound(a) + speedBound(b);
        if (speed <= 0.0) {
            return;
        }
        double step = SAMPLE_SPACING / speed;
        double clear = from;
        if (touch(a, b, from)) {
            stop(a, b, from, from);
            return;
        }
        for (double t = Math.min(to, from + step); ; t = Math.min(to, t + step)) {
            if (touch(a, b, t)) {
                double contact = narrow(a, b, clear, t);
                stop(a, b, contact, from);
                return;
            }
            clear = t;
            if (t >= to) {
                return;
            }
        }
    }

    /** The first touching time in (clear, touching], to {@link #PRECISION}. */
    private static double narrow(Robot a, Robot b, double clear, double touching) {
        while (touching - clear > PRECISION) {
            double mid = 0.5 * (clear + touching);
            if (touch(a, b, mid)) {
                touching = mid;
            } else {
                clear = mid;
            }
        }
        return touching;
    }

    private static boolean touch(Robot a, Robot b, double t) {
        return RobotShapes.overlap(edgesAt(a, t), edgesAt(b, t));
    }

    private static RsSegment[][] edgesAt(Robot r, double t) {
        return r.shapes().edgesAt(r.motion().getPoseAtTime(t));
    }

    /** Upper bound of the speed of any point of the robot's shapes under its current motion. */
    private static double speedBound(Robot r) {
        RsMotion m = r.motion();
        if (!r.isMoving() || m == null) {
            return 0.0;
        }
        return Math.abs(m.getVelocity()) + Math.abs(m.getTurnRate()) * r.shapes().reach();
    }

    /** A box holding the robot's shapes throughout [from, to]. */
    private static RsRectangle swept(Robot r, double from, double to) {
        RsRectangle box = RobotShapes.bounds(edgesAt(r, from));
        double grow = speedBound(r) * (to - from) + SAMPLE_SPACING;
        box.setBounds(box.x - grow, box.y - grow, box.width + 2 * grow, box.height + 2 * grow);
        return box;
    }

    /**
     * Stops each moving robot of the pair before {@code contact} (not before {@code now}); the contact
     * sensors of both that touch the other robot go hot with its name: a stopped robot's when its
     * motion ends, a robot at rest's at the time the other one stops.
     */
    private static void stop(Robot a, Robot b, double contact, double now) {
        List<RsBodyContactSensor> touchingA = touching(a, b, contact);
        List<RsBodyContactSensor> touchingB = touching(b, a, contact);
        double stopA = stopOne(a, contact, now);
        double stopB = stopOne(b, contact, now);
        press(a, b, touchingA, stopA, stopB);
        press(b, a, touchingB, stopB, stopA);
    }

    /** Cuts the robot's motion before the contact; returns the stop time, or NaN if it was not moving into it. */
    private static double stopOne(Robot r, double contact, double now) {
        RsMotion m = r.motion();
        if (!r.isMoving() || m == null) {
            return Double.NaN;
        }
        double stopAt = Math.max(now, m.time0 + Math.max(0.0, Math.floor(1000.0 * (contact - m.time0) - 0.1) / 1000.0));
        if (stopAt >= m.time1) {
            return Double.NaN;
        }
        m.stopMotionAtTime(stopAt);
        m.collision = true;
        m.collisionTime = contact - m.time0;
        r.getBody().setCollision(true);
        return stopAt;
    }

    /** The robot's contact sensors that touch the other robot at the moment of contact (both motions as requested). */
    private static List<RsBodyContactSensor> touching(Robot r, Robot other, double contact) {
        RsSegment[][] otherEdges = edgesAt(other, contact);
        RsTransform pose = r.motion().getPoseAtTime(contact);
        List<RsBodyContactSensor> touching = new ArrayList<>();
        for (RsBodySensor s : r.getBody().getBodySensorArray()) {
            if (s instanceof RsBodyContactSensor
                    && RobotShapes.distance(outlineAt((RsBodyContactSensor) s, pose), otherEdges) <= TOUCHING) {
                touching.add((RsBodyContactSensor) s);
            }
        }
        return touching;
    }

    /**
     * A robot that was stopped has exactly its touching sensors flagged, to go hot when its motion ends;
     * one at rest has them pressed when the other robot has stopped.
     */
    private static void press(Robot r, Robot other, List<RsBodyContactSensor> touching, double ownStop, double otherStop) {
        if (!Double.isNaN(ownStop)) {
            for (RsBodySensor s : r.getBody().getBodySensorArray()) {
                if (s instanceof RsBodyContactSensor) {
                    boolean touches = touching.contains(s);
                    ((RsBodyContactSensor) s).setCollision(touches, touches ? other.getLabel() : null);
                }
            }
        } else if (!touching.isEmpty() && !Double.isNaN(otherStop)) {
            r.touchedAt(otherStop, touching, other.getLabel());
        }
    }

    private static RsSegment[] outlineAt(RsBodyContactSensor c, RsTransform pose) {
        RsSegment[] ref = c.getSegmentArray();
        RsSegment[] out = new RsSegment[ref.length];
        for (int i = 0; i < ref.length; i++) {
            out[i] = new RsSegment();
            pose.map2(ref[i], out[i]);
        }
        return out;
    }
}
