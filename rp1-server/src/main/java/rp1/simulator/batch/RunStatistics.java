package rp1.simulator.batch;

import java.util.ArrayList;
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
 * Watches a run for its results: per robot, where it is, how far it went (summed motion by motion,
 * exactly), how many of its motions ended in a collision (reported to its client or not), how many
 * events its client was sent, and its trail, sampled at every change of the world. An observer: it
 * changes nothing, so a run watched is the run unwatched. Called on the thread running tasks.
 */
public final class RunStatistics implements WorldListener, Simulation.EventListener {
    /** Trail points closer than this to the previous one are left out, metres. */
    private static final double TRAIL_RESOLUTION = 0.01;

    private final Map<Integer, Watched> robots = new LinkedHashMap<>();
    private final Map<Integer, Long> eventsByClient = new HashMap<>();

    private RunStatistics() {
    }

    /** Starts watching {@code simulation} (before its run starts). */
    public static RunStatistics watch(Simulation simulation) {
        RunStatistics s = new RunStatistics();
        simulation.getWorld().addListener(s);
        simulation.addEventListener(s);
        return s;
    }

    @Override
    public synchronized void worldChanged(World world, double simTime) {
        for (Robot r : world.getRobots()) {
            robots.computeIfAbsent(r.getNumber(), n -> new Watched(r.getLabel())).see(r);
        }
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
        Watched w = robots.computeIfAbsent(r.getNumber(), n -> new Watched(r.getLabel()));
        w.client = session.getNumber();
        if (event instanceof RsMotionHaltedEvent h && h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            w.collisions++;
        }
    }

    /**
     * The robots at the end, in the order they joined; call once the run has stopped, with the world
     * it ran (robots still in it are looked at a last time; those that left keep what was last seen).
     */
    public synchronized List<RobotResult> results(World world) {
        worldChanged(world, Double.NaN);
        List<String> names = names();
        List<RobotResult> out = new ArrayList<>();
        int i = 0;
        for (Watched w : robots.values()) {
            out.add(new RobotResult(names.get(i++), w.x, w.y, w.heading, w.distance(), w.collisions,
                    eventsByClient.getOrDefault(w.client, 0L)));
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
            for (List<Double> p : w.pieces) {
                pieces.add(Trail.piece(p));
            }
            out.add(new Trail(names.get(i++), pieces));
        }
        return out;
    }

    /** What is known of one robot. */
    private static final class Watched {
        final String label;
        int client;
        int collisions;
        double x;
        double y;
        double heading;
        /** Distance of the motions that are over. */
        double travelled;
        RsMotion motion;
        int series = Integer.MIN_VALUE;
        final List<List<Double>> pieces = new ArrayList<>();

        Watched(String label) {
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
            heading = pose.getTheta();
            if (r.isPlaced()) {
                sample(m.getContinuitySeriesID());
            }
        }

        private void sample(int id) {
            List<Double> piece = pieces.isEmpty() ? null : pieces.get(pieces.size() - 1);
            if (id != series || piece == null) {
                series = id;
                piece = new ArrayList<>();
                pieces.add(piece);
            } else if (Math.hypot(x - piece.get(piece.size() - 2), y - piece.get(piece.size() - 1)) < TRAIL_RESOLUTION) {
                return;
            }
            piece.add(x);
            piece.add(y);
        }

        double distance() {
            return travelled + covered(motion);
        }

        /** How far the body origin went along {@code m} so far (its speed is constant along it). */
        private static double covered(RsMotion m) {
            return m == null ? 0.0 : Math.abs(m.getVelocity()) * (m.time - m.time0);
        }
    }
}
