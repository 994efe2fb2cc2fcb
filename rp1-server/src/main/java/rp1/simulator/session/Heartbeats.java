package rp1.simulator.session;

import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;

/**
 * Every client's heartbeat (docs/behavior.md section 4.3), driven by one task: beat k of a heartbeat
 * started at U with interval i is due at exactly U + k i (no drift), sequence numbers 1, 2, 3, ...; the
 * heartbeats of all clients that fall due at the same time go out together, in the order the
 * heartbeats were started, after every other task due then ({@link Scheduler#LATE}). Sent in one task,
 * their events are acknowledged in parallel instead of one interlocked round trip after another.
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
    private final PriorityQueue<Beat> due = new PriorityQueue<>();
    private TaskHandle queued = TaskHandle.NONE;
    private double queuedTime = Double.NaN;
    private long started;

    public Heartbeats(Scheduler scheduler) {
        this.scheduler = scheduler;
    }

    /** Starts a heartbeat of {@code interval} seconds from {@code start}; stop it with {@link Beat#stop()}. */
    Beat start(Beater beater, double start, double interval) {
        Beat b = new Beat(beater, start, interval, started++);
        due.add(b);
        requeue();
        return b;
    }

    @Override
    public void run(double time) {
        queued = TaskHandle.NONE;
        List<Beat> now = new ArrayList<>();
        while (!due.isEmpty() && due.peek().next <= time) {
            now.add(due.poll());
        }
        for (Beat b : now) {
            if (!b.stopped) {
                b.sequence++;
                b.beater.beat(b.next, b.sequence);
            }
            if (!b.stopped) {
                b.next = b.start + (b.sequence + 1) * b.interval;
                due.add(b);
            }
        }
        requeue();
    }

    /** Keeps the task queued at the earliest beat still to come. */
    private void requeue() {
        while (!due.isEmpty() && due.peek().stopped) {
            due.poll();
        }
        if (due.isEmpty()) {
            queued.cancel();
            queued = TaskHandle.NONE;
            return;
        }
        double first = due.peek().next;
        if (queued.isScheduled() && queuedTime == first) {
            return;
        }
        queued.cancel();
        queuedTime = first;
        queued = scheduler.schedule(first, Scheduler.LATE, this);
    }

    /** One client's heartbeat. */
    final class Beat implements Comparable<Beat> {
        private final Beater beater;
        private final double start;
        private final double interval;
        private final long order;
        private double next;
        private int sequence;
        private boolean stopped;

        private Beat(Beater beater, double start, double interval, long order) {
            this.beater = beater;
            this.start = start;
            this.interval = interval;
            this.order = order;
            this.next = start + interval;
        }

        /** No more beats; a beat due at this very moment is not sent. */
        void stop() {
            stopped = true;
            requeue();
        }

        @Override
        public int compareTo(Beat o) {
            int c = Double.compare(next, o.next);
            return c != 0 ? c : Long.compare(order, o.order);
        }
    }
}
