package rp1.simulator.scheduler;

import java.util.HashMap;
import java.util.Map;
import java.util.TreeSet;

/**
 * The simulation's task queue and dispatch loop (behavior.md sections 4.1 and 4.2). Tasks run one at
 * a time, in order of time, then priority (higher first: ordinary tasks 1, heartbeats 0, so at equal
 * times heartbeats come last), then insertion sequence. Immediate tasks have time 0 and so precede
 * every timed task. A task object is in the queue at most once.
 *
 * <p>Threads: request readers queue tasks and read the current time {@link #now()}; the interlock
 * stops and starts the clock; one thread runs {@link #runLoop()} (or a test calls {@link #runNext()}).
 * All state is guarded by this object's monitor; tasks run outside it.
 */
public final class Scheduler {
    /** Priority of ordinary tasks. */
    public static final int NORMAL = 1;
    /** Priority of heartbeats: last among tasks due at the same time. */
    public static final int HEARTBEAT = 0;
    /** The original re-checks its queue at least this often while idle. */
    private static final long IDLE_RECHECK_MILLIS = 5000;

    private final SimClock clock;
    private final TreeSet<Entry> queue = new TreeSet<>();
    private final Map<Task, Entry> queued = new HashMap<>();
    private long sequence;
    private boolean stopped;
    /** A task is running (on the dispatch loop or on a thread that restarted the clock). */
    private boolean executing;

    public Scheduler(SimClock clock) {
        this.clock = clock;
    }

    public SimClock getClock() {
        return clock;
    }

    /**
     * Queues {@code task} at {@code time}. If the same task object is already queued nothing changes
     * (the recycled motion task relies on this).
     *
     * @return false if the task was already queued
     */
    public synchronized boolean schedule(double time, int priority, Task task) {
        return enqueue(false, time, priority, task);
    }

    /** Queues {@code task} to run before every timed task, at the then-current time. */
    public synchronized boolean scheduleImmediate(Task task) {
        return enqueue(true, 0.0, NORMAL, task);
    }

    private boolean enqueue(boolean immediate, double time, int priority, Task task) {
        if (queued.containsKey(task)) {
            return false;
        }
        Entry e = new Entry(immediate, time, priority, sequence++, task);
        queue.add(e);
        queued.put(task, e);
        // The loop only needs waking if it can run the new task sooner than what it waits for: with
        // the clock stopped (the interlock is open) it waits for the restart, which wakes it anyway.
        if (clock.isRunning() && queue.first() == e) {
            notifyAll();
        }
        return true;
    }

    /** Removes {@code task} from the queue; returns whether it was queued. */
    public synchronized boolean cancel(Task task) {
        Entry e = queued.remove(task);
        if (e == null) {
            return false;
        }
        queue.remove(e);
        notifyAll();
        return true;
    }

    /** Whether {@code task} is waiting in the queue. */
    public synchronized boolean isScheduled(Task task) {
        return queued.containsKey(task);
    }

    /** The number of queued tasks. */
    public synchronized int size() {
        return queue.size();
    }

    /**
     * The current simulation time, brought up to date with the wall clock ("U" in the spec): what
     * request handlers stamp their tasks with.
     */
    public synchronized double now() {
        return clock.update(horizon());
    }

    /** Time of the first queued timed task, or infinity. */
    private double horizon() {
        for (Entry e : queue) {
            if (!e.immediate) {
                return e.time;
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Starts the clock (at simulation start, and when the interlock is released). */
    public synchronized void startClock() {
        clock.start();
        notifyAll();
    }

    /** Freezes the clock (the interlock is open); no task runs until it is started again. */
    public synchronized void stopClock() {
        clock.stop(horizon());
    }

    public synchronized boolean isClockRunning() {
        return clock.isRunning();
    }

    /**
     * Runs the next task if one may run now, without waiting: the clock must be running and, for a
     * paced clock, the task due. Lockstep simulations and tests drive the scheduler with this.
     *
     * @return whether a task ran
     */
    public boolean runNext() {
        Entry e;
        synchronized (this) {
            if (executing) {
                return false;
            }
            e = takeDue();
            if (e == null) {
                return false;
            }
            executing = true;
        }
        execute(e);
        return true;
    }

    /** Runs a taken task; afterwards another thread may take the next one. */
    private void execute(Entry e) {
        try {
            e.task.run(e.runTime);
        } finally {
            synchronized (this) {
                executing = false;
                notifyAll();
            }
        }
    }

    /**
     * Runs the tasks that may run now on the calling thread, one after the other, until none may
     * (the clock stopped, nothing due) or another thread is running one; returns how many ran. Tests
     * drive the scheduler with it; so does the thread that restarts the clock (a client's reader, on
     * the acknowledgement of the newest event): the next task then runs without first waking the
     * dispatch loop, which saves one thread hand-off per interlocked exchange. Tasks still run one at
     * a time, in queue order.
     */
    public int runUntilIdle() {
        int n = 0;
        while (runNext()) {
            n++;
        }
        return n;
    }

    /**
     * The head task if it may run now (removed from the queue), else null. Holds the monitor. A timed
     * task runs at its own time (the clock jumps there in lockstep; a paced clock has just reached it);
     * an immediate task runs at the current time. A task queued in the past (a negative timeout) runs
     * at once, stamped with its own time, and does not pull the clock back.
     */
    private Entry takeDue() {
        if (stopped || !clock.isRunning() || queue.isEmpty()) {
            return null;
        }
        Entry head = queue.first();
        double now = clock.update(horizon());
        if (!head.immediate && head.time > now) {
            if (!clock.isLockstep()) {
                return null;
            }
            clock.setSimTime(head.time);
            now = head.time;
        }
        queue.pollFirst();
        queued.remove(head.task);
        head.runTime = head.immediate ? now : head.time;
        return head;
    }

    /**
     * The dispatch loop: waits while the clock is stopped or nothing is due, sleeping in wall time
     * until the next task is due on a paced clock, and runs tasks in order. Returns after
     * {@link #shutdown()}.
     */
    public void runLoop() {
        try {
            while (true) {
                Entry e = awaitNext();
                if (e == null) {
                    return;
                }
                execute(e);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private synchronized Entry awaitNext() throws InterruptedException {
        while (!stopped) {
            Entry e = executing ? null : takeDue();
            if (e != null) {
                executing = true;
                return e;
            }
            wait(executing ? IDLE_RECHECK_MILLIS : waitMillis());
        }
        return null;
    }

    /** How long to wait before looking again: until the head is due on a running paced clock. */
    private long waitMillis() {
        if (!clock.isRunning() || queue.isEmpty() || clock.isLockstep()) {
            return IDLE_RECHECK_MILLIS;
        }
        Entry head = queue.first();
        return Math.max(1L, Math.min(IDLE_RECHECK_MILLIS, clock.millisUntil(head.time)));
    }

    /** Makes {@link #runLoop()} return and {@link #runNext()} refuse to run anything. */
    public synchronized void shutdown() {
        stopped = true;
        notifyAll();
    }

    /** A queued task: immediate ones first, then by time, higher priority first, insertion order. */
    private static final class Entry implements Comparable<Entry> {
        final boolean immediate;
        final double time;
        final int priority;
        final long sequence;
        final Task task;
        double runTime;

        Entry(boolean immediate, double time, int priority, long sequence, Task task) {
            this.immediate = immediate;
            this.time = time;
            this.priority = priority;
            this.sequence = sequence;
            this.task = task;
        }

        @Override
        public int compareTo(Entry o) {
            if (immediate != o.immediate) {
                return immediate ? -1 : 1;
            }
            int c = Double.compare(time, o.time);
            if (c != 0) {
                return c;
            }
            c = Integer.compare(o.priority, priority);
            return c != 0 ? c : Long.compare(sequence, o.sequence);
        }
    }
}
