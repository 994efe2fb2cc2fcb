package rp1.web;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.event.RsEvent;
import rp1.simulator.Simulation;
import rp1.simulator.record.EventText;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.TaskHandle;
import rp1.simulator.session.ClientSession;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.TrailSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;
import rp1.simulator.world.World;
import rp1.simulator.world.WorldListener;

/**
 * Gathers a run for the page, as it happens: at every simulated time at which the world changed
 * (every modelling step of a moving robot, a placement, a target selected, trails removed) a
 * snapshot of it as that time left it, with the range and target sensors' readings; and every event
 * sent to a client, as its event-log line. It only reads, in observer tasks (which run after the
 * model tasks due at their time, are not counted among them and move no clock), and sends nothing,
 * so a traced run is the run untraced (docs/recording.md).
 *
 * <p>What is gathered leaves in {@link #drain() chunks} of the page's encoding, each continuing
 * where the one before stopped: a replay page holds them all, a live page gets them as they come.
 * Thread-safe: the simulation's thread adds, any thread drains.
 */
public final class RunTrace implements WorldListener, Simulation.EventListener, AutoCloseable {
    private final Simulation simulation;
    private final Scheduler scheduler;
    private final Chunk chunk = new Chunk();
    /** The capture queued for the latest change, and the time it runs at. */
    private TaskHandle queued = TaskHandle.NONE;
    private double queuedTime;
    /** The latest time of a change that came while a capture at an earlier time was queued. */
    private double later = Double.NEGATIVE_INFINITY;
    private boolean closed;

    private RunTrace(Simulation simulation) {
        this.simulation = simulation;
        this.scheduler = simulation.getScheduler();
    }

    /**
     * Starts tracing {@code simulation}'s world and events. Attach before the simulation runs, on the
     * thread that will run it or before it is started.
     */
    public static RunTrace attach(Simulation simulation) {
        RunTrace trace = new RunTrace(simulation);
        simulation.getWorld().addListener(trace);
        simulation.addEventListener(trace);
        return trace;
    }

    /** The header of the page's data: the floor plan, as JSON. */
    public String planJson() {
        Json j = new Json().beginObject().key("v").value(1);
        PlanJson.write(j, simulation.getWorld().getPlan());
        return j.endObject().toString();
    }

    /**
     * On the thread running tasks: the world changed. One capture is queued for the time of the
     * change, an observer that runs after every model task due then, so a frame shows the world as
     * that time left it, however many robots moved at it.
     */
    @Override
    public synchronized void worldChanged(World world, double simTime) {
        double t = Double.isNaN(simTime) ? scheduler.recordedTime() : simTime;
        if (closed) {
            return;
        }
        if (!queued.isScheduled()) {
            queue(t);
        } else if (t > queuedTime) {
            // The capture queued is due first; the one for this change follows it.
            later = Math.max(later, t);
        }
    }

    private void queue(double t) {
        queuedTime = t;
        queued = scheduler.observeAt(t, this::capture);
    }

    private synchronized void capture(double simTime) {
        if (closed) {
            return;
        }
        chunk.frame(Capture.of(WorldSnapshot.of(simulation.getWorld(), simTime)));
        if (later > simTime) {
            queue(later);
        }
        later = Double.NEGATIVE_INFINITY;
    }

    @Override
    public synchronized void event(ClientSession session, RsEvent event, boolean delivered) {
        if (delivered && !closed) {
            chunk.event(EventText.line(session.getNumber(), event));
        }
    }

    /** What was gathered since the last drain, as one chunk of JSON (docs/recording.md). Any thread. */
    public synchronized String drain() {
        return chunk.take();
    }

    /**
     * Stops tracing, once the simulation has stopped: a capture still queued (the run stopped at its
     * time, before its observers ran) is taken now. What was gathered can still be drained.
     */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        if (queued.cancel()) {
            chunk.frame(Capture.of(WorldSnapshot.of(simulation.getWorld(), queuedTime)));
        }
        closed = true;
        simulation.getWorld().removeListener(this);
    }

    /**
     * A snapshot with the sensor readings it does not hold, read at the same moment.
     *
     * @param readings per robot in the snapshot, per part: a range sensor's range (Double), a target
     *                 sensor's target (String or null), else null
     */
    record Capture(WorldSnapshot snapshot, List<Object[]> readings) {
        static Capture of(WorldSnapshot snapshot) {
            List<Object[]> readings = new ArrayList<>();
            for (RobotSnapshot r : snapshot.robots()) {
                Object[] values = new Object[r.parts().size()];
                for (int i = 0; i < values.length; i++) {
                    RsBodyPart part = r.parts().get(i).part();
                    if (part instanceof RsBodyRangeSensor s) {
                        values[i] = s.getRange();
                    } else if (part instanceof RsBodyTargetSensor s) {
                        values[i] = s.getTargetName();
                    }
                }
                readings.add(values);
            }
            return new Capture(snapshot, readings);
        }
    }

    /** The encoder: what the page already has, and what has been gathered since. */
    private static final class Chunk {
        private final StringBuilder times = new StringBuilder();
        private final Map<Integer, RobotTrack> robots = new LinkedHashMap<>();
        private final Map<Object, SegmentTrack> segments = new IdentityHashMap<>();
        private final List<SegmentTrack> segmentOrder = new ArrayList<>();
        private final StringBuilder selection = new StringBuilder();
        private final List<String> events = new ArrayList<>();
        private boolean[] selected;
        private int frames;
        private long lastNanos;

        void event(String line) {
            events.add(line);
        }

        void frame(Capture c) {
            WorldSnapshot s = c.snapshot();
            int f = frames++;
            long nanos = Math.round(s.simTime() * 1e9);
            Encoding.append(times, nanos - lastNanos);
            lastNanos = nanos;
            selection(f, s);
            List<RobotSnapshot> present = s.robots();
            Set<Integer> numbers = new HashSet<>();
            for (int i = 0; i < present.size(); i++) {
                RobotSnapshot r = present.get(i);
                numbers.add(r.number());
                robots.computeIfAbsent(r.number(), n -> new RobotTrack(r)).frame(f, r, c.readings().get(i));
            }
            for (Map.Entry<Integer, RobotTrack> t : robots.entrySet()) {
                if (!numbers.contains(t.getKey())) {
                    t.getValue().absent(f);
                }
            }
            IdentityHashMap<Object, Boolean> shown = new IdentityHashMap<>();
            for (TrailSnapshot t : s.trails()) {
                shown.put(t.segment(), Boolean.TRUE);
                SegmentTrack track = segments.get(t.segment());
                if (track == null) {
                    track = new SegmentTrack(segmentOrder.size(), t);
                    segments.put(t.segment(), track);
                    segmentOrder.add(track);
                }
                track.frame(f, t);
            }
            for (SegmentTrack track : segmentOrder) {
                if (!shown.containsKey(track.segment())) {
                    track.gone(f);
                }
            }
        }

        private void selection(int f, WorldSnapshot s) {
            List<Boolean> now = s.targetSelected();
            if (selected == null) {
                selected = new boolean[now.size()];
                Arrays.fill(selected, true);
            }
            for (int i = 0; i < selected.length; i++) {
                if (now.get(i) != selected[i]) {
                    selected[i] = now.get(i);
                    Encoding.append(selection, f, i, selected[i] ? 1 : 0);
                }
            }
        }

        String take() {
            Json j = new Json().beginObject();
            j.key("t").raw("[" + times + "]");
            times.setLength(0);
            j.key("robots").beginArray();
            for (RobotTrack t : robots.values()) {
                t.take(j);
            }
            j.endArray().key("segs").beginArray();
            for (SegmentTrack t : segmentOrder) {
                t.take(j);
            }
            j.endArray().key("sel").raw("[" + selection + "]");
            selection.setLength(0);
            j.key("ev").beginArray();
            for (String e : events) {
                j.value(e);
            }
            events.clear();
            return j.endArray().endObject().toString();
        }
    }
}
