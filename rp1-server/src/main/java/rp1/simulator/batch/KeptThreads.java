package rp1.simulator.batch;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import rp1.simulator.launch.HelperThreads;

/**
 * The threads a sweep's servers in this process run their client starters and stops on, kept from
 * one run to the next instead of a new one for each (docs/performance.md). As many as are busy at
 * once, each let go after a minute idle; daemons, since the sweep waits for every run it starts. A
 * thread takes the task's name while it runs it, so a stack dump or a log still says which it is,
 * and the context class loader of the thread that started the task, as a new thread would have
 * inherited it: a robot's thread started by the client starter sees its own run's classes.
 */
final class KeptThreads implements HelperThreads, AutoCloseable {
    private static final String IDLE = "rp1-run-helper";
    private static final long KEEP_ALIVE_SECONDS = 60;

    private final AtomicInteger made = new AtomicInteger();
    /**
     * The group of the thread that made this, for every kept thread: not the group of whichever thread
     * asked first (a robot's, when a robot's thread asks the server to stop), whose threads are ended
     * with its run.
     */
    private final ThreadGroup group = Thread.currentThread().getThreadGroup();
    private final ExecutorService threads = new ThreadPoolExecutor(0, Integer.MAX_VALUE, KEEP_ALIVE_SECONDS,
            TimeUnit.SECONDS, new SynchronousQueue<>(), task -> {
                Thread t = new Thread(group, task, IDLE + "-" + made.incrementAndGet());
                t.setDaemon(true);
                // Not the loader of the run that happened to make it: an idle thread keeps no run's classes.
                t.setContextClassLoader(KeptThreads.class.getClassLoader());
                return t;
            });

    @Override
    public void start(String name, boolean daemon, Runnable task) {
        ClassLoader context = Thread.currentThread().getContextClassLoader();
        Runnable kept = () -> {
            Thread self = Thread.currentThread();
            String idle = self.getName();
            ClassLoader before = self.getContextClassLoader();
            self.setName(name);
            self.setContextClassLoader(context);
            try {
                task.run();
            } finally {
                // A task that left its thread interrupted must not pass that on to the next one.
                Thread.interrupted();
                self.setContextClassLoader(before);
                self.setName(idle);
            }
        };
        try {
            threads.execute(kept);
        } catch (RejectedExecutionException e) {
            // Closed (the sweep is over): a stop asked for late still happens, on a thread of its own.
            HelperThreads.in(group).start(name, daemon, task);
        }
    }

    /** Lets the threads go once their tasks are done; tasks started later get threads of their own. */
    @Override
    public void close() {
        threads.shutdown();
    }
}
