package rp1.simulator.launch;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Ends the threads that outlive the run they belong to. A robot's handler that never returns holds
 * the thread running the simulation's tasks; a robot's {@code run()} that never returns holds its own
 * thread. In a server of its own the process ends with them, but in a sweep's process ({@code
 * --isolation loader}) or a Spark task they would keep a processor busy through every run after, and
 * a stopped run would wait for them. So each thread is given what is left of a grace period to end by
 * itself, then interrupted (a thread asleep or waiting ends), then, still alive, stopped with {@link
 * Thread#stop()}, which Java 17 still carries out. A thread that catches the stop (a loop around
 * {@code catch (Throwable t)}) or a later Java, which refuses to stop threads, leaves it running: the
 * caller is told, so that a sweep can carry its later runs out in processes of their own.
 */
final class StuckThreads {
    /**
     * A thread that did not end by itself: "thread "NAME" in FRAME", and how it ended ("ended when
     * interrupted", "stopped", or "still running" and why).
     */
    record Ended(String thread, String how, boolean stillRunning) {
        @Override
        public String toString() {
            return thread + ": " + how;
        }
    }

    /** How long the threads are waited for before any is looked at. */
    private static final long FIRST_WAIT_MILLIS = 50;

    /** How long an interrupted, then a stopped, thread is given to end. */
    static final long AFTER_EACH_STEP_MILLIS = 500;

    private StuckThreads() {
    }

    /**
     * Waits for the threads to end, at most {@code graceMillis} for all of them together, then ends those
     * still alive as the class comment says.
     *
     * @return each thread that did not end by itself: its name, where it was, and how it ended
     */
    static List<Ended> end(List<Thread> threads, long graceMillis) throws InterruptedException {
        // Most threads end at once; only those that do not are looked at (a stack costs a pause of the thread).
        List<Thread> late = joinAll(threads, Math.min(graceMillis, FIRST_WAIT_MILLIS));
        // A thread in System.exit is waiting for the shutdown hooks, among them whoever called this:
        // waiting for it would wait for ever, and stopping it would stop the process's exit.
        List<Thread> others = new ArrayList<>();
        for (Thread t : late) {
            if (!ExitCaller.isExiting(t.getStackTrace())) {
                others.add(t);
            }
        }
        List<Thread> alive = joinAll(others, Math.max(0, graceMillis - FIRST_WAIT_MILLIS));
        if (alive.isEmpty()) {
            return List.of();
        }
        List<String> where = new ArrayList<>();
        for (Thread t : alive) {
            where.add(describe(t));
            t.interrupt();
        }
        List<Thread> unmoved = joinAll(alive, AFTER_EACH_STEP_MILLIS);
        boolean refused = false;
        for (Thread t : unmoved) {
            refused |= !stop(t);
        }
        List<Thread> unstoppable = joinAll(unmoved, AFTER_EACH_STEP_MILLIS);
        List<Ended> ended = new ArrayList<>();
        for (int i = 0; i < alive.size(); i++) {
            Thread t = alive.get(i);
            boolean running = unstoppable.contains(t);
            String how = running ? "still running" + (refused ? " (this Java does not stop threads)" : " (it caught the stop)")
                    : unmoved.contains(t) ? "stopped" : "ended when interrupted";
            ended.add(new Ended(where.get(i), how, running));
        }
        return ended;
    }

    /** The threads still alive once each has been waited for, all within {@code millis}. */
    private static List<Thread> joinAll(List<Thread> threads, long millis) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        List<Thread> alive = new ArrayList<>();
        for (Thread t : threads) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (left > 0) {
                t.join(left);
            }
            if (t.isAlive()) {
                alive.add(t);
            }
        }
        return alive;
    }

    /**
     * "thread "NAME" in FRAME", FRAME the innermost method it was running outside the JDK (the robot's,
     * where a robot holds it), else the innermost.
     */
    private static String describe(Thread t) {
        StackTraceElement[] stack = t.getStackTrace();
        StackTraceElement frame = stack.length == 0 ? null : stack[0];
        for (StackTraceElement e : stack) {
            if (e.getModuleName() == null || !e.getModuleName().startsWith("java.")) {
                frame = e;
                break;
            }
        }
        return "thread \"" + t.getName() + "\"" + (frame == null ? "" : " in " + ExitCaller.shown(frame));
    }

    // Thread.stop is deprecated because the stopped thread's locks are let go with its objects half
    // changed. Here those objects are the run's own, which nobody reads after it; the alternative is a
    // thread that computes for ever in a process that goes on with other runs.
    /** Stops the thread; false if this Java refuses to (after Java 19). */
    @SuppressWarnings({"deprecation", "removal"})
    private static boolean stop(Thread t) {
        try {
            t.stop();
            return true;
        } catch (UnsupportedOperationException e) {
            return false;
        }
    }
}
