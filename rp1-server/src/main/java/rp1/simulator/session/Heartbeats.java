package rp1.simulator.session;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.TreeMap;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;

/**
 * Every client's heartbeat (docs/behavior.md section 4.3), driven by one task: beat k of a heartbeat
 * started at U with interval i is due at exactly U + k i (no drift), sequence numbers 1, 2, 3, ...; the
 * heartbeats of all clients that fall due at the same time go out together, in the order the
 * heartbeats were started, after every other task due then ({@link Scheduler#LATE}). Sent in one task,
 * their events are acknowledged in parallel instead of one interlocked round trip after another.
 * Beats are kept by the time they are due: a crowd's heartbeats mostly fall due together, and taking
 * a thousand beats off a heap, one comparison chain each, cost more than sending them.
 */
public final class Heartbeats implements Task {
    /**
     * The shortest interval a client gets, in simulated seconds; a shorter one is raised to it. It is the
     * finest modelling interval the server accepts: nothing in the world changes faster, and a beat
     * every 1e-300 s would hold simulated time still for everyone while the client reads.
     */
    public static final double MIN_INTERVAL = 0.001;

    /** Where a beat goes. */
    @FunctionalInterface
    interface Beater {
        void beat(double time, int sequence);
    }

    private final Scheduler scheduler;
    /** The beats to come by the time they are due; each time's beats in the order their heartbeats started. */
    private final TreeMap<Double, DueTogether> due = new TreeMap<>();
    private TaskHandle queued = TaskHandle.NONE;
    private double queuedTime = Double.NaN;
    private long started;

    public Heartbeats(Scheduler scheduler) {
        this.scheduler = scheduler;
    }

    /** Starts a heartbeat of {@code interval} seconds from {@code start}; stop it with {@link Beat#stop()}. */
    Beat start(Beater beater, double start, double interval) {
        Beat b = new Beat(beater, start, interval, started++);
        file(b);
        requeue();
        return b;
    }

    @Override
    public void run(double time) {
        queued = TaskHandle.NONE;
        List<Beat> now = new ArrayList<>();
        while (!due.isEmpty() && due.firstKey() <= time) {
            for (Beat b : due.pollFirstEntry().getValue().inOrder()) {
                b.filedIn = null;
                now.add(b);
            }
        }
        for (Beat b : now) {
            if (!b.stopped) {
                b.sequence++;
                b.beater.beat(b.next, b.sequence);
            }
            if (!b.stopped) {
                b.next = b.start + (b.sequence + 1) * b.interval;
                file(b);
            }
        }
        requeue();
    }

    private void file(Beat b) {
        DueTogether together = due.computeIfAbsent(b.next, t -> new DueTogether());
        together.add(b);
        b.filedIn = together;
    }

    /**
     * Keeps the task queued at the earliest beat still to come (stopped beats are not): a time whose
     * beats have all stopped goes. Stopped beats are counted, not searched for, so that starting or
     * stopping one of ten thousand heartbeats does not look at the others.
     */
    private void requeue() {
        while (!due.isEmpty() && due.firstEntry().getValue().live == 0) {
            due.pollFirstEntry();
        }
        if (due.isEmpty()) {
            queued.cancel();
            queued = TaskHandle.NONE;
            return;
        }
        double first = due.firstKey();
        if (queued.isScheduled() && queuedTime == first) {
            return;
        }
        queued.cancel();
        queuedTime = first;
        queued = scheduler.schedule(first, Scheduler.LATE, this);
    }

    /** The beats due at one time, in the order their heartbeats started once {@link #inOrder} is asked. */
    private static final class DueTogether {
        private static final Comparator<Beat> STARTED = Comparator.comparingLong(b -> b.order);
        private final List<Beat> beats = new ArrayList<>();
        /** Whether {@link #beats} is in starting order (beats arrive from different times). */
        private boolean inOrder = true;
        /** How many of {@link #beats} have not stopped. */
        private int live;

        void add(Beat b) {
            if (!beats.isEmpty() && beats.get(beats.size() - 1).order > b.order) {
                inOrder = false;
            }
            beats.add(b);
            live++;
        }

        List<Beat> inOrder() {
            if (!inOrder) {
                beats.sort(STARTED);
                inOrder = true;
            }
            return beats;
        }
    }

    /** One client's heartbeat. */
    final class Beat {
        private final Beater beater;
        private final double start;
        private final double interval;
        private final long order;
        private double next;
        private int sequence;
        private boolean stopped;
        /** The beats due together this one is filed with, or null while it is being sent. */
        private DueTogether filedIn;

        private Beat(Beater beater, double start, double interval, long order) {
            this.beater = beater;
            this.start = start;
            this.interval = interval;
            this.order = order;
            this.next = start + interval;
        }

        /** No more beats; a beat due at this very moment is not sent. */
        void stop() {
            if (!stopped) {
                stopped = true;
                if (filedIn != null) {
                    filedIn.live--;
                }
            }
            requeue();
        }
    }
}
