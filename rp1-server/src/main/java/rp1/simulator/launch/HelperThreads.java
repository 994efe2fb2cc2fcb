package rp1.simulator.launch;

/**
 * Where a server runs the two short tasks it gives a thread of their own: starting the loaded clients
 * one after another ({@code dlc start}) and stopping ({@code shutdown}). A server of its own starts a
 * new thread for each ({@link #newThreads()}); a sweep, which runs thousands of servers in one process,
 * hands them to threads it keeps (a new thread costs a stack mapped and unmapped, the JVM's
 * bookkeeping and two hand-offs between threads: a twentieth of a long sweep's time, as
 * docs/performance.md measures). The client starter runs no robot code; the stop runs only a robot's
 * shutdown handler, as its session closes. A thread-local value could pass from one run's stop to the
 * next on a kept thread only through a thread-local the robot's classes do not own: one they own is
 * made anew with every run, since a class holding one in a static field is loaded anew for every run
 * ({@code StaticState}). The simulation's own thread, which runs the robots' handlers, is always new.
 */
@FunctionalInterface
public interface HelperThreads {
    /**
     * A thread of its own for each task, named {@code name}, in the group of the thread that calls this;
     * a daemon if {@code daemon} (the process waits for a server's stop, not for its client starter).
     * Not in the group of whichever thread asks: a robot's handler may ask the server to stop, and the
     * threads of a robot's group are ended with its run.
     */
    static HelperThreads newThreads() {
        return in(Thread.currentThread().getThreadGroup());
    }

    /** A thread of its own for each task, in {@code group} (see {@link #newThreads()}). */
    static HelperThreads in(ThreadGroup group) {
        return (name, daemon, task) -> {
            Thread t = new Thread(group, task, name);
            t.setDaemon(daemon);
            t.start();
        };
    }

    /**
     * Runs {@code task} on a thread other than the caller's, named {@code name} while it runs.
     *
     * @param daemon whether a thread of its own would be a daemon (kept threads always are: whoever
     *               keeps them waits for the servers it starts)
     */
    void start(String name, boolean daemon, Runnable task);
}
