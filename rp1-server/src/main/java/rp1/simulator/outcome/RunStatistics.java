package rp1.simulator.outcome;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import rp1.rossum.RsMotion;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.simulator.Simulation;
import rp1.simulator.session.ClientSession;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;
import rp1.simulator.world.WorldListener;

/**
 * Watches a run for its results: per robot, where it was first placed, where it is, how far it went
 * (summed motion by motion, exactly), how many of its motions ended in a collision (reported to its
 * client or not) and when the first did, how many events its client was sent, and its trail, sampled
 * at every change of the world; at the end, what its client reported of its own. An observer: it
 * changes nothing, so a run watched is the run unwatched. Called on the thread running tasks.
 */
public final class RunStatistics implements WorldListener, Simulation.EventListener {
    /** Trail points closer than this to the previous one are left out, metres. */
    private static final double TRAIL_RESOLUTION = 0.01;
    /** Trail points within this of the line through their neighbours are left out, metres. */
    private static final double TRAIL_TOLERANCE = 0.002;

    private final Map<Integer, Watched> robots = new LinkedHashMap<>();
    private final Map<Integer, Long> eventsByClient = new HashMap<>();
    private final Simulation simulation;

    private RunStatistics(Simulation simulation) {
        this.simulation = simulation;
    }

    /** Starts watching {@code simulation} (before its run starts). */
    public static RunStatistics watch(Simulation simulation) {
        RunStatistics s = new RunStatistics(simulation);
        simulation.getWorld().addListener(s);
        simulation.addEventListener(s);
        return s;
    }

    @Override
    public synchronized void worldChanged(World world, double simTime) {
        for (Robot r : world.getRobots()) {
            watched(r).see(r);
        }
    }

    /**
     * The robot's record, made when first asked for. Not with {@code computeIfAbsent}: a sweep's runs
     * use the quick compiler only, whose code builds a lambda that captures by a method handle, and
     * at every change of the world that was a twentieth of the simulation's time.
     */
    private Watched watched(Robot r) {
        Watched w = robots.get(r.getNumber());
        if (w == null) {
            w = new Watched(r.getNumber(), r.getLabel());
            robots.put(r.getNumber(), w);
        }
        return w;
    }

    @Override
    public synchronized void event(ClientSession session, RsEvent event, boolean delivered) {
        if (delivered) {
            eventsByClient.merge(session.getNumber(), 1L, Long::sum);
        }
        Robot r = session.getRobot();
        if (r == null) {
            return;
        }
        Watched w = watched(r);
        w.client = session.getNumber();
        if (event instanceof RsMotionHaltedEvent h && h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            if (w.collisions++ == 0) {
                w.firstCollision = h.simTime;
            }
        }
    }

    /**
     * The robots at {@code endTime}, in the order they joined; call once the run has stopped, with
     * the simulated time it stopped at (robots still in the world are looked at a last time, and
     * their pose and distance are taken at that time; those that left keep what was last seen).
     */
    public synchronized List<RobotResult> results(double endTime) {
        World world = simulation.getWorld();
        worldChanged(world, Double.NaN);
        List<String> names = names();
        List<RobotResult> out = new ArrayList<>();
        int i = 0;
        for (Watched w : robots.values()) {
            boolean present = world.getRobots().stream().anyMatch(r -> r.getNumber() == w.number);
            RobotResult.Pose end = w.start == RobotResult.Pose.NONE ? RobotResult.Pose.NONE
                    : present ? w.poseAt(endTime) : new RobotResult.Pose(w.x, w.y, w.heading());
            out.add(new RobotResult(names.get(i++), w.start, end, present ? w.distanceAt(endTime) : w.distance(),
                    w.collisions, w.firstCollision, eventsByClient.getOrDefault(w.client, 0L),
                    simulation.getReportedResults().of(w.client)));
        }
        return out;
    }

    /** The robots' names, in joining order, with {@code #N} (their number) where names repeat. */
    private List<String> names() {
        Map<String, Integer> counts = new HashMap<>();
        for (Watched w : robots.values()) {
            counts.merge(w.label, 1, Integer::sum);
        }
        List<String> names = new ArrayList<>();
        for (Map.Entry<Integer, Watched> e : robots.entrySet()) {
            String label = e.getValue().label;
            names.add(counts.get(label) > 1 ? label + "#" + e.getKey() : label);
        }
        return names;
    }

    /** Every robot's trail, in the order they joined, named as in {@link #results} (call after it). */
    public synchronized List<Trail> trails() {
        List<Trail> out = new ArrayList<>();
        List<String> names = names();
        int i = 0;
        for (Watched w : robots.values()) {
            List<double[]> pieces = new ArrayList<>();
            for (Points p : w.pieces) {
                pieces.add(Trail.simplified(p.toArray(), TRAIL_TOLERANCE));
            }
            out.add(new Trail(names.get(i++), pieces));
        }
        return out;
    }

    /** What is known of one robot. */
    private static final class Watched {
        final int number;
        final String label;
        int client;
        int collisions;
        double firstCollision = Double.NaN;
        RobotResult.Pose start = RobotResult.Pose.NONE;
        double x;
        double y;
        /** The heading's cosine and sine as last seen (the angle itself is only worked out if asked for). */
        double cos;
        double sin;
        /** Distance of the motions that are over. */
        double travelled;
        RsMotion motion;
        int series = Integer.MIN_VALUE;
        final List<Points> pieces = new ArrayList<>();

        Watched(int number, String label) {
            this.number = number;
            this.label = label;
        }

        void see(Robot r) {
            RsMotion m = r.getBody().getMotion();
            if (m == null) {
                return;
            }
            if (m != motion) {
                travelled += covered(motion);
                motion = m;
            }
            RsTransform pose = r.pose();
            x = pose.m13;
            y = pose.m23;
            cos = pose.m11;
            sin = pose.m21;
            if (r.isPlaced()) {
                if (start == RobotResult.Pose.NONE) {
                    RsTransform first = m.transform0 != null ? m.transform0 : pose;
                    start = new RobotResult.Pose(first.m13, first.m23, first.getTheta());
                }
                sample(m.getContinuitySeriesID());
            }
        }

        private void sample(int id) {
            Points piece = pieces.isEmpty() ? null : pieces.get(pieces.size() - 1);
            if (id != series || piece == null) {
                series = id;
                piece = new Points();
                pieces.add(piece);
            } else if (piece.closeToLast(x, y, TRAIL_RESOLUTION)) {
                return;
            }
            piece.add(x, y);
        }

        /** The heading last seen, radians (as {@link RsTransform#getTheta()} gives it). */
        double heading() {
            return Math.atan2(sin, cos);
        }

        double distance() {
            return travelled + covered(motion);
        }

        /** The distance at {@code t}, on or after the last change seen: the current motion taken to {@code t}. */
        double distanceAt(double t) {
            if (motion == null || !(t >= motion.time0)) {
                return distance();
            }
            return travelled + Math.abs(motion.getVelocity()) * (Math.min(t, motion.time1) - motion.time0);
        }

        /** The pose at {@code t} along the current motion (the last pose seen if there is none). */
        RobotResult.Pose poseAt(double t) {
            if (motion == null || Double.isNaN(t)) {
                return new RobotResult.Pose(x, y, heading());
            }
            RsTransform p = motion.getPoseAtTime(t);
            return new RobotResult.Pose(p.m13, p.m23, p.getTheta());
        }

        /** How far the body origin went along {@code m} so far (its speed is constant along it). */
        private static double covered(RsMotion m) {
            return m == null ? 0.0 : Math.abs(m.getVelocity()) * (m.time - m.time0);
        }
    }

    /** A piece of trail as it grows: x0, y0, x1, y1, ... without a boxed number per coordinate. */
    private static final class Points {
        private double[] xy = new double[64];
        private int size;

        void add(double x, double y) {
            if (size + 2 > xy.length) {
                xy = Arrays.copyOf(xy, 2 * xy.length);
            }
            xy[size++] = x;
            xy[size++] = y;
        }

        /** Whether (x, y) is within {@code distance} of the last point. */
        boolean closeToLast(double x, double y, double distance) {
            return Trail.shorter(x - xy[size - 2], y - xy[size - 1], distance);
        }

        double[] toArray() {
            return Arrays.copyOf(xy, size);
        }
    }
}
