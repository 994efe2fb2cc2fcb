package rp1.simulator.launch;

/**
 * Where a server runs the two short tasks it gives a thread of their own: starting the loaded clients
 * one after another ({@code dlc start}) and stopping ({@code shutdown}). A server of its own starts a
 * new thread for each ({@link #NEW_THREADS}); a sweep, which runs thousands of servers in one process,
 * hands them to threads it keeps (a new thread costs a stack mapped and unmapped, the JVM's
 * bookkeeping and two hand-offs between threads, and two of them per run were a fifth of a bumper
 * run's cost: docs/performance.md). Neither task runs a robot's code, so a kept thread carries nothing of one
 * run into the next. The simulation's own thread, which runs the robots' handlers, is always new.
 */
@FunctionalInterface
public interface HelperThreads {
    /**
     * A thread of its own for each task, named {@code name}; a daemon if {@code daemon} (the process
     * waits for a server's stop, not for its client starter).
     */
    HelperThreads NEW_THREADS = (name, daemon, task) -> {
        Thread t = new Thread(task, name);
        t.setDaemon(daemon);
        t.start();
    };

    /**
     * Runs {@code task} on a thread other than the caller's, named {@code name} while it runs.
     *
     * @param daemon whether a thread of its own would be a daemon (kept threads always are: whoever
     *               keeps them waits for the servers it starts)
     */
    void start(String name, boolean daemon, Runnable task);
}
