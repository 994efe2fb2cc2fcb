package rp1.simulator.scheduler;

import java.util.ArrayDeque;
import java.util.PriorityQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;

/**
 * The simulation's task queue and the right to run it (docs/behavior.md sections 4.1 and 4.2).
 *
 * <p><b>Order.</b> Immediate tasks first, in the order queued; then timed tasks by time, then priority
 * (higher first), then the order queued. Model tasks use {@link #NORMAL} or {@link #LATE} (heartbeats,
 * which come after every ordinary task due at the same time). Observers ({@link #observeAt},
 * {@link #observeNow}: pictures, the time limit) come after every model task due at their time, change
 * nothing the clients can see, and are not counted in {@link #modelTasksRun()}, so a run observed
 * differently is the same run.
 *
 * <p><b>Inputs and boundaries.</b> What reaches the simulation from outside (client requests, mouse
 * clicks) is not applied where it arrives: the arriving thread queues it and calls
 * {@link #inputsArrived()}, and the thread running tasks applies it at the next boundary between two
 * tasks, through the {@link Boundary}, stamped with the current time. So every change to the model
 * happens on the thread that runs tasks, at a point of the task sequence that can be recorded. Inputs
 * are applied before the run {@link #begin() begins} too (at time 0: clients connect and send their
 * first requests before anything moves), but not while the interlock has stopped the clock; those that
 * arrived while it was stopped (a client's answers to the event it was handling) are stamped with the
 * time it stopped at, before a paced clock catches up with the wall time the client took.
 *
 * <p><b>Threads.</b> One thread at a time holds the right to run tasks and cross boundaries: the
 * dispatch loop ({@link #runLoop()}), or any thread that calls {@link #pump(long)} and finds the right
 * free (a transport thread that has just released the interlock or handed over inputs runs what is
 * then due itself, saving a thread hand-off per exchange), or a test calling {@link #runNext()}. Handing the right over goes
 * through this scheduler's lock, so each holder sees everything the previous one did. Queuing, the
 * clock's stop and resume, and {@link #now()} may be called from any thread.
 */
public final class Scheduler {
    /** Priority of ordinary tasks. */
    public static final int NORMAL = 1;
    /** Priority of heartbeats: after every {@link #NORMAL} task due at the same time. */
    public static final int LATE = 0;
    /** Observers: after every model task due at the same time. */
    private static final int OBSERVER = -1;
    /** The dispatch loop re-checks its queue at least this often while idle. */
    private static final long IDLE_RECHECK_NANOS = TimeUnit.SECONDS.toNanos(5);

    /** Applies the inputs that arrived since the last boundary. */
    @FunctionalInterface
    public interface Boundary {
        /** Called between two tasks by the thread that runs them; {@code simTime} is the current time. */
        void cross(double simTime);
    }

    private enum Step { TASK, BOUNDARY, NONE }

    private final SimClock clock;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition workAvailable = lock.newCondition();
    private final ArrayDeque<Entry> immediate = new ArrayDeque<>();
    private final PriorityQueue<Entry> timed = new PriorityQueue<>();
    /** What waits until nothing else can run ({@link #whenIdle}). */
    private final ArrayDeque<Runnable> idleActions = new ArrayDeque<>();
    private Boundary boundary;
    private Consumer<RuntimeException> failureHandler = e -> {
        throw e;
    };
    private long sequence;
    private int size;
    private boolean inputsPending;
    /** Inputs arrived while the interlock had stopped the clock: answers to an event, stamped with its time. */
    private boolean inputsWhileStopped;
    private boolean shutDown;
    /** The thread that holds the right to run tasks, or null. */
    private Thread executor;
    /**
     * Written and read by the holder of the right to run tasks (handing the right over goes through the
     * lock, which publishes it); others read it only once the scheduler has stopped. Not volatile: it
     * changes with every task.
     */
    private long modelTasksRun;

    public Scheduler(SimClock clock) {
        this.clock = clock;
    }

    /** Where inputs are applied between tasks. Set once, before anything runs. */
    public void setBoundary(Boundary boundary) {
        this.boundary = boundary;
    }

    /**
     * What happens when a task, an input or an idle action throws: by default the exception goes up to
     * whoever runs it.
     */
    public void setFailureHandler(Consumer<RuntimeException> handler) {
        this.failureHandler = handler;
    }

    /** Something run for the scheduler (an input applied at a boundary) threw {@code e}: handled as a failing task. */
    public void failed(RuntimeException e) {
        failureHandler.accept(e);
    }

    // ---------------------------------------------------------------------------------------------
    // Queuing.

    /** Queues a model task at {@code time}; returns its handle. */
    public TaskHandle schedule(double time, int priority, Task task) {
        return enqueue(false, time, priority, true, task);
    }

    /** Queues a model task to run before every timed task, stamped {@code stamp}. */
    public TaskHandle scheduleImmediate(double stamp, Task task) {
        return enqueue(true, stamp, NORMAL, true, task);
    }

    /** Queues an observer to run at {@code time}, after every model task due then. */
    public TaskHandle observeAt(double time, Task observer) {
        return enqueue(false, time, OBSERVER, false, observer);
    }

    /** Queues an observer to run before the next timed task, at the current time. */
    public TaskHandle observeNow(Task observer) {
        lock.lock();
        try {
            return enqueue(true, clock.update(horizon()), OBSERVER, false, observer);
        } finally {
            lock.unlock();
        }
    }

    /** A time that is not a number would sort after every other and stall a paced clock's horizon. */
    private TaskHandle enqueue(boolean isImmediate, double time, int priority, boolean model, Task task) {
        if (Double.isNaN(time)) {
            throw new IllegalArgumentException("task time is not a number");
        }
        lock.lock();
        try {
            Entry e = new Entry(time, priority, sequence++, model, task);
            if (isImmediate) {
                immediate.addLast(e);
            } else {
                timed.add(e);
            }
            size++;
            signalIfIdle();
            return e;
        } finally {
            lock.unlock();
        }
    }

    /** The number of queued tasks. */
    public int size() {
        lock.lock();
        try {
            return size;
        } finally {
            lock.unlock();
        }
    }

    /**
     * The time of the task that runs next (an immediate one's stamp, else the first timed one's), or
     * infinity if none is queued: a replay stopping at a given time looks at it.
     */
    public double nextTaskTime() {
        lock.lock();
        try {
            Entry e = peekImmediate();
            return e != null ? e.time : horizon();
        } finally {
            lock.unlock();
        }
    }

    /** Time of the first queued timed task, or infinity. Holds the lock. */
    private double horizon() {
        Entry e = peekTimed();
        return e == null ? Double.POSITIVE_INFINITY : e.time;
    }

    private Entry peekTimed() {
        Entry e = timed.peek();
        while (e != null && e.cancelled) {
            timed.poll();
            e = timed.peek();
        }
        return e;
    }

    private Entry peekImmediate() {
        Entry e = immediate.peekFirst();
        while (e != null && e.cancelled) {
            immediate.pollFirst();
            e = immediate.peekFirst();
        }
        return e;
    }

    // ---------------------------------------------------------------------------------------------
    // The clock.

    /**
     * The current simulation time, brought up to date with the wall clock ("U" in the spec). Inputs
     * are stamped with it at the boundary where they are applied.
     */
    public double now() {
        lock.lock();
        try {
            return clock.update(horizon());
        } finally {
            lock.unlock();
        }
    }

    /** The time last recorded, without consulting the wall clock (what log lines show). */
    public double recordedTime() {
        lock.lock();
        try {
            return clock.getSimTime();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Moves a lockstep clock on to {@code time} (never back): a replay sets the time a recorded input
     * was applied at before applying it, as the recorded run's clock then read. Paced clocks ignore it.
     */
    public void advanceTo(double time) {
        lock.lock();
        try {
            if (clock.isLockstep() && time > clock.getSimTime()) {
                clock.setSimTime(time);
            }
        } finally {
            lock.unlock();
        }
    }

    /** Begins the run: the clock starts at the current time (0 for a new simulation). */
    public void begin() {
        lock.lock();
        try {
            clock.begin();
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** The interlock opened: time freezes and no task runs until {@link #resumeClock()}. */
    public void stopClock() {
        lock.lock();
        try {
            clock.stop(horizon());
        } finally {
            lock.unlock();
        }
    }

    /**
     * The interlock closed. Due work is not started here: the caller runs it ({@link #pump(long)}), or
     * whoever holds the right to run tasks finds it when it lets go.
     */
    public void resumeClock() {
        lock.lock();
        try {
            clock.resume();
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** Whether tasks may run: the run has begun and the interlock is closed. */
    public boolean isClockRunning() {
        lock.lock();
        try {
            return clock.canRun();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Whether nothing runs and nothing could run now without something new: no thread holds the right
     * to run tasks, no input waits and no queued task is due (it lies beyond a held or paced clock, or
     * the interlock has stopped the clock). With a task queued, an idle lockstep clock is held.
     */
    public boolean isIdle() {
        lock.lock();
        try {
            return executor == null && !hasWork();
        } finally {
            lock.unlock();
        }
    }

    /** Time may not advance until {@link #release()}; tasks and inputs due now still run. */
    public void hold() {
        lock.lock();
        try {
            clock.hold();
        } finally {
            lock.unlock();
        }
    }

    /** Ends a {@link #hold()}. */
    public void release() {
        lock.lock();
        try {
            clock.release();
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /**
     * The user paused the run: simulated time stops where it is now, between two tasks. Inputs are
     * still applied (at that time), as at any boundary; what waits until nothing else can run
     * ({@link #whenIdle}) waits for the run to go on, so it happens at the same point of the run.
     */
    public void pause() {
        lock.lock();
        try {
            clock.pause(horizon());
        } finally {
            lock.unlock();
        }
    }

    /** Ends a {@link #pause()}: time runs on from where it stood. */
    public void unpause() {
        lock.lock();
        try {
            clock.unpause();
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** Lets {@code seconds} more of simulated time pass (pausing first if the run goes on), then stands still. */
    public void step(double seconds) {
        lock.lock();
        try {
            clock.step(horizon(), seconds);
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** Whether the user has paused the run. */
    public boolean isPaused() {
        lock.lock();
        try {
            return clock.isPaused();
        } finally {
            lock.unlock();
        }
    }

    /**
     * From now on, {@code speed} simulated seconds per wall second, or lockstep for infinity
     * ({@code simulationSpeed=max}); time runs on from where it is. A replay stays lockstep.
     */
    public void setSpeed(double speed) {
        lock.lock();
        try {
            clock.setSpeed(horizon(), speed);
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** Simulated seconds per wall second now; infinity in lockstep. */
    public double getSpeed() {
        lock.lock();
        try {
            return clock.getSpeed();
        } finally {
            lock.unlock();
        }
    }

    /** Whether the clock is lockstep now (the speed is max, or a replay). */
    public boolean isLockstep() {
        lock.lock();
        try {
            return clock.isLockstep();
        } finally {
            lock.unlock();
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Running.

    /** Inputs are waiting: the next boundary applies them. Any thread. */
    public void inputsArrived() {
        lock.lock();
        try {
            inputsPending = true;
            inputsWhileStopped |= clock.isStopped();
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Runs {@code action} on the thread running tasks at the first boundary at which nothing else can
     * run: no task may run now, no input is waiting and the interlock does not hold the clock. That
     * point of the task sequence does not depend on when {@code action} was handed over, as long as it
     * was before it (the interlock's departures of clients that owe nothing wait for it). Any thread.
     */
    public void whenIdle(Runnable action) {
        lock.lock();
        try {
            idleActions.addLast(action);
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Model tasks run so far (observers not counted): the place in the task sequence. Call on the thread
     * running tasks, or after the scheduler has stopped.
     */
    public long modelTasksRun() {
        return modelTasksRun;
    }

    /**
     * Crosses a pending boundary and runs the next task, if one may run now, on the calling thread.
     * Tests drive the scheduler with it.
     *
     * @return whether a task ran
     */
    public boolean runNext() {
        if (!tryAcquire()) {
            return false;
        }
        try {
            Step s;
            do {
                s = step();
            } while (s == Step.BOUNDARY);
            return s == Step.TASK;
        } finally {
            releaseRight();
        }
    }

    /** Runs tasks on the calling thread until none may run now; returns how many ran. */
    public int runUntilIdle() {
        int n = 0;
        while (runNext()) {
            n++;
        }
        return n;
    }

    /**
     * Runs what may run now on the calling thread for at most {@code budgetNanos}, if no other thread
     * is running tasks; then lets go and wakes the dispatch loop, which takes over what remains or
     * waits anew for the next deadline (it may have been waiting without one while this thread held
     * the right). A transport thread calls this after releasing the interlock or delivering inputs.
     */
    public void pump(long budgetNanos) {
        if (!tryAcquire()) {
            return;
        }
        long deadline = System.nanoTime() + budgetNanos;
        try {
            while (step() != Step.NONE && System.nanoTime() - deadline < 0) {
                continue;
            }
        } finally {
            releaseRight();
        }
    }

    /**
     * The dispatch loop: whenever no other thread runs tasks and there is work, takes the right to run
     * them and runs until none may run; sleeps until the next task is due on a paced clock. Returns
     * after {@link #shutdown()}.
     */
    public void runLoop() {
        try {
            while (awaitRight()) {
                try {
                    while (step() != Step.NONE) {
                        continue;
                    }
                } finally {
                    releaseRight();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private boolean awaitRight() throws InterruptedException {
        lock.lock();
        try {
            while (!shutDown) {
                if (executor == null && hasWork()) {
                    executor = Thread.currentThread();
                    return true;
                }
                workAvailable.awaitNanos(executor == null ? waitNanos() : IDLE_RECHECK_NANOS);
            }
            return false;
        } finally {
            lock.unlock();
        }
    }

    /** Makes {@link #runLoop()} return and every other way of running refuse. */
    public void shutdown() {
        lock.lock();
        try {
            shutDown = true;
            workAvailable.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /**
     * After {@link #shutdown()}: waits until no thread is running a task any more (a thread that was in
     * the middle of one finishes it), at most {@code timeoutMillis}; returns whether none is. What is
     * read from the model afterwards (the picture at exit, the end of a recording) is then final.
     */
    public boolean awaitIdle(long timeoutMillis) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        lock.lock();
        try {
            while (executor != null) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                workAvailable.awaitNanos(left);
            }
            return true;
        } finally {
            lock.unlock();
        }
    }

    /** The thread running a task now, or null: after {@link #awaitIdle} failed, the one that holds on. */
    public Thread runningTasks() {
        lock.lock();
        try {
            return executor;
        } finally {
            lock.unlock();
        }
    }

    private boolean tryAcquire() {
        lock.lock();
        try {
            if (executor != null || shutDown) {
                return false;
            }
            executor = Thread.currentThread();
            return true;
        } finally {
            lock.unlock();
        }
    }

    private void releaseRight() {
        lock.lock();
        try {
            executor = null;
            if (shutDown) {
                workAvailable.signalAll();
            }
            signalIfIdle();
        } finally {
            lock.unlock();
        }
    }

    /** Wakes the dispatch loop if nobody is running tasks and something may run. Holds the lock. */
    private void signalIfIdle() {
        if (executor == null && !shutDown) {
            workAvailable.signalAll();
        }
    }

    /** One boundary crossing or one task, by the holder of the right to run. */
    private Step step() {
        Entry e;
        double boundaryTime;
        Runnable idle = null;
        lock.lock();
        try {
            if (shutDown || clock.isStopped()) {
                return Step.NONE;
            }
            if (inputsPending && boundary != null) {
                inputsPending = false;
                boundaryTime = inputsWhileStopped ? clock.getSimTime() : clock.update(horizon());
                inputsWhileStopped = false;
                e = null;
            } else {
                e = clock.isBegun() ? takeDue() : null;
                if (e == null) {
                    idle = clock.isPaused() ? null : idleActions.pollFirst();
                    if (idle == null) {
                        return Step.NONE;
                    }
                }
                boundaryTime = 0.0;
            }
        } finally {
            lock.unlock();
        }
        if (idle != null) {
            try {
                idle.run();
            } catch (RuntimeException ex) {
                failureHandler.accept(ex);
            }
            return Step.BOUNDARY;
        }
        if (e == null) {
            boundary.cross(boundaryTime);
            return Step.BOUNDARY;
        }
        try {
            e.task.run(e.time);
        } catch (RuntimeException ex) {
            failureHandler.accept(ex);
        }
        if (e.model) {
            modelTasksRun++;
        }
        return Step.TASK;
    }

    /** Whether the holder of the right could do something now. Holds the lock. */
    private boolean hasWork() {
        if (shutDown || clock.isStopped()) {
            return false;
        }
        if ((inputsPending && boundary != null) || (!idleActions.isEmpty() && !clock.isPaused())) {
            return true;
        }
        if (!clock.isBegun()) {
            return false;
        }
        if (peekImmediate() != null) {
            return true;
        }
        Entry head = peekTimed();
        return head != null && isDue(head);
    }

    /**
     * Whether a timed task may run now: a paced clock has reached its time, or a lockstep clock that
     * is not held (nor paused before that time) may jump there. Holds the lock.
     */
    private boolean isDue(Entry head) {
        return head.time <= clock.update(head.time) || clock.mayJumpTo(head.time);
    }

    /**
     * The head task if it may run now (removed from the queue), else null. Holds the lock. A timed
     * task runs at its own time (the clock jumps there in lockstep; a paced clock has just reached
     * it); an immediate task at the time it was stamped with. A task queued in the past (a negative
     * timeout) runs at once, stamped with its own time, and does not pull the clock back.
     */
    private Entry takeDue() {
        Entry head = peekImmediate();
        if (head != null) {
            immediate.pollFirst();
            return taken(head);
        }
        head = peekTimed();
        if (head == null) {
            return null;
        }
        if (!isDue(head)) {
            return null;
        }
        if (head.time > clock.getSimTime()) {
            clock.setSimTime(head.time);
        }
        timed.poll();
        return taken(head);
    }

    private Entry taken(Entry e) {
        e.queued = false;
        size--;
        return e;
    }

    /** How long the dispatch loop sleeps: until the head is due on a running paced clock. */
    private long waitNanos() {
        if (!clock.canRun() || clock.isLockstep() || clock.isHeld()) {
            return IDLE_RECHECK_NANOS;
        }
        Entry head = peekTimed();
        if (head == null || head.time > clock.limit()) {
            return IDLE_RECHECK_NANOS;
        }
        return Math.max(1L, Math.min(IDLE_RECHECK_NANOS, clock.nanosUntil(head.time)));
    }

    /**
     * A queued task and its handle. Timed ones are ordered by time, higher priority first, then order
     * queued; immediate ones wait in their own queue, in order, and run at the time they were stamped.
     */
    private final class Entry implements Comparable<Entry>, TaskHandle {
        final double time;
        final int priority;
        final long sequence;
        final boolean model;
        final Task task;
        boolean queued = true;
        boolean cancelled;

        Entry(double time, int priority, long sequence, boolean model, Task task) {
            this.time = time;
            this.priority = priority;
            this.sequence = sequence;
            this.model = model;
            this.task = task;
        }

        @Override
        public boolean cancel() {
            lock.lock();
            try {
                if (!queued) {
                    return false;
                }
                queued = false;
                cancelled = true;
                size--;
                return true;
            } finally {
                lock.unlock();
            }
        }

        @Override
        public boolean isScheduled() {
            lock.lock();
            try {
                return queued;
            } finally {
                lock.unlock();
            }
        }

        @Override
        public int compareTo(Entry o) {
            int c = Double.compare(time, o.time);
            if (c != 0) {
                return c;
            }
            c = Integer.compare(o.priority, priority);
            return c != 0 ? c : Long.compare(sequence, o.sequence);
        }
    }
}
