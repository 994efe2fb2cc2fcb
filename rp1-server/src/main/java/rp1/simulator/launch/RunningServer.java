package rp1.simulator.launch;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import rp1.simulator.Simulation;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.net.ClientListener;
import rp1.simulator.net.ClientRegistry;
import rp1.simulator.record.RunRecords;
import rp1.simulator.scheduler.Scheduler;

/**
 * A server that has started: its threads (the scheduler's dispatch loop, the network thread, a reader
 * per client over pipes, a thread per loaded client until it is called directly or its {@code run()}
 * returns, a writer for a client that falls behind; behavior.md section 3.2, docs/architecture.md)
 * are running. It stops when asked ({@link #stop()},
 * Ctrl-C through {@code rp1.Server}'s shutdown hook, the view's exit), at {@code maxSimulationTime},
 * when every loaded client is done ({@code exitWhenClientsDone}), when a max-speed run has nobody
 * left ({@link #NOBODY_LEFT}), or when a loaded client fails to
 * initialize. Stopping closes every client, stops the scheduler, finishes the recording and event log
 * (if any), ends the threads a robot's code holds past the stop ({@link StuckThreads}) and flushes and
 * closes the log; the exit status says how it ended ({@link ExitStatus}),
 * {@link ExitStatus#OUTPUT_FAILED} if it ended as asked but its recording, event log or a picture
 * could not be written.
 */
public final class RunningServer {
    /**
     * How long stopping waits for the scheduler to finish the task it is running, and then for the
     * loaded clients' threads to end, before it ends them ({@link StuckThreads}).
     */
    private static final long GRACE_MILLIS = 2000;
    /** How long a thread waiting for the server waits for the thread the stop was handed to, before doing it itself. */
    private static final long STOP_BEGINS_NANOS = TimeUnit.SECONDS.toNanos(1);

    /** The stop reason of a max-speed run that every client and robot has left ({@link #endWhenDeserted}). */
    public static final String NOBODY_LEFT = "nobody-left";
    /** The stop reason while the server runs. */
    private static final String RUNNING = "running";
    /** Made beforehand: the stop reason of a simulation that ran out of memory, when no other string can be made. */
    private static final String OUT_OF_MEMORY = "the simulation failed: " + OutOfMemoryError.class.getName();

    private final Parts parts;
    private final Thread scheduler;
    private final AtomicBoolean stopping = new AtomicBoolean();
    /** Set as {@link #shutDown} begins: it runs once, on whichever thread gets there first. */
    private final AtomicBoolean shutDownBegun = new AtomicBoolean();
    /** The status the first stop request asked for, for a waiting thread that takes the stop over. */
    private volatile int requestedStatus = ExitStatus.OK;
    /** When the stop was handed to a thread ({@link System#nanoTime()}); 0 while none was. */
    private volatile long stopHandedAt;
    private final CountDownLatch exited = new CountDownLatch(1);
    private volatile int exitStatus = ExitStatus.OK;
    private volatile String stopReason = RUNNING;
    private volatile AutoCloseable view = () -> { };
    /** What {@link #threadsLeftRunning} returns. */
    private final List<String> leftRunning = new CopyOnWriteArrayList<>();

    /** What {@link ServerLauncher} built, handed over to run. */
    static final class Parts {
        final ServerConfig config;
        final ServerLog log;
        final Simulation simulation;
        final ClientRegistry registry;
        final ClientListener listener;
        final ClientLauncher launcher;
        final ViewHook viewHook;
        final RunRecords records;
        final HelperThreads helpers;

        Parts(ServerConfig config, ServerLog log, Simulation simulation, ClientRegistry registry,
              ClientListener listener, ClientLauncher launcher, ViewHook viewHook, RunRecords records,
              HelperThreads helpers) {
            this.config = config;
            this.log = log;
            this.simulation = simulation;
            this.registry = registry;
            this.listener = listener;
            this.launcher = launcher;
            this.viewHook = viewHook;
            this.records = records;
            this.helpers = helpers;
        }
    }

    private RunningServer(Parts parts) {
        this.parts = parts;
        // Among the robots' threads: a handler it calls may start threads, which are ended with the run.
        this.scheduler = new Thread(parts.launcher.robotThreads(), this::simulate, "scheduler");
        scheduler.setDaemon(true);
    }

    /**
     * The scheduler thread: runs the simulation until it is shut down. An Error that ends it (out of
     * memory in a task) first stops the run with {@link ExitStatus#FATAL_ERROR} and a log line, so that
     * its files are closed and whoever waits for it (a sweep, whose other runs go on) learns at once
     * instead of waiting for a run that never ends; then it goes on up, to the process's handler
     * ({@link FatalErrors} in a server of its own). With no memory left for a thread to stop it on,
     * this thread stops it itself: it has nothing else left to do.
     */
    private void simulate() {
        try {
            parts.simulation.runPaused();
        } catch (Error e) {
            String reason = failedBecause(e);
            try {
                parts.log.important("The simulation failed and stops: " + e);
            } catch (Error again) {
                // Out of memory still: the stop below matters more than the line.
            } finally {
                try {
                    requestStop(ExitStatus.FATAL_ERROR, reason);
                } catch (Error noThread) {
                    stopHere(ExitStatus.FATAL_ERROR, reason);
                }
            }
            throw e;
        }
    }

    /**
     * "the simulation failed: " and the error; the error's class alone when even that string cannot be
     * made (a sweep tells a run that ran out of memory by its class's name in the reason).
     */
    private static String failedBecause(Error e) {
        try {
            return "the simulation failed: " + e;
        } catch (Error again) {
            return e instanceof OutOfMemoryError ? OUT_OF_MEMORY : "the simulation failed";
        }
    }

    /** Starts the view, the scheduler, the listener and the loaded clients, then the clock. */
    static RunningServer begin(Parts parts) throws StartupException {
        RunningServer server = new RunningServer(parts);
        try {
            server.openView();
            server.startThreads();
        } catch (StartupException e) {
            parts.log.important("Fatal error: " + e.getMessage());
            server.shutDown(e.getExitStatus());
            throw e;
        }
        return server;
    }

    private void openView() throws StartupException {
        try {
            view = parts.viewHook.open(new ViewHook.Context(parts.simulation, parts.config, parts.log,
                    () -> requestStop(ExitStatus.OK)));
        } catch (IOException e) {
            // Files and ports the view was asked for: their messages name them.
            throw new StartupException("cannot open the view: " + e.getMessage());
        } catch (Exception e) {
            throw new StartupException("cannot open the view: " + LoadedClient.describe(e));
        }
    }

    private void startThreads() throws StartupException {
        ServerConfig c = parts.config;
        parts.log.log("Starting main scheduler loop with simulation speed: " + (c.lockstep ? "max" : c.simulationSpeed));
        parts.log.log("modelingFrameInterval (sec): " + c.modelingInterval);
        scheduler.start();
        scheduleMaxTime();
        endWhenDeserted();
        if (parts.listener != null) {
            parts.listener.start();
        }
        // In lockstep the clock waits until the loaded clients have started, in order (ClientLauncher).
        boolean waitForClients = c.lockstep && !parts.launcher.isEmpty();
        try {
            parts.launcher.launch(parts.simulation, parts.registry, getPort(), new ClientOutcome(), parts.helpers,
                    waitForClients ? parts.simulation::startClock : () -> { });
        } catch (IOException e) {
            throw new StartupException("cannot launch the loaded clients: " + e.getMessage());
        }
        if (!waitForClients) {
            parts.simulation.startClock();
        }
        if (c.lockstep && !c.enableNetworkClients && parts.launcher.isEmpty()) {
            // Nobody can ever come: the run is deserted from its start, and would wait for ever.
            endDeserted("No client is loaded and network clients are disabled: at simulationSpeed=max simulated"
                    + " time stands still without a robot, so nothing can happen; the run ends here");
        }
    }

    private void scheduleMaxTime() {
        double max = parts.config.maxSimulationTime;
        if (Double.isInfinite(max)) {
            return;
        }
        parts.simulation.stopAt(max, () -> {
            parts.log.log("maxSimulationTime " + max + " s reached");
            requestStop(ExitStatus.OK, "max-simulation-time");
        });
    }

    /**
     * At {@code simulationSpeed=max} time cannot pass without a robot on the floor. When every client
     * has left and no robot is left, the run ends, unless a client may still come and nothing else
     * would end it (network clients and no time limit: the server waits, as it waits for its first
     * client) or loaded clients end it ({@code exitWhenClientsDone}).
     */
    private void endWhenDeserted() {
        ServerConfig c = parts.config;
        boolean timeLimit = !Double.isInfinite(c.maxSimulationTime);
        if (!c.lockstep || c.exitWhenClientsDone || (c.enableNetworkClients && !timeLimit)) {
            return;
        }
        String why = timeLimit ? "maxSimulationTime (" + c.maxSimulationTime + " s) can never be reached"
                : "network clients are disabled, so nothing more can happen";
        parts.simulation.whenDeserted(() -> endDeserted("No robot is left and no client is connected: at"
                + " simulationSpeed=max simulated time stands still and " + why + "; the run ends here"));
    }

    /** Ends a max-speed run that no robot is in and none can come to, saying {@code why} in the log. */
    private void endDeserted(String why) {
        parts.simulation.shutdown();
        parts.log.log(why);
        requestStop(ExitStatus.OK, NOBODY_LEFT);
    }

    /** How loaded clients end the server. */
    private final class ClientOutcome implements ClientLauncher.Outcome {
        @Override
        public void clientFailed(String failure) {
            requestStop(ExitStatus.CLIENT_FAILED, "client failed: " + failure);
        }

        @Override
        public void allFinished(String firstFailure) {
            if (parts.config.exitWhenClientsDone) {
                parts.log.log("Every loaded client has finished (exitWhenClientsDone)");
                if (firstFailure == null) {
                    requestStop(ExitStatus.OK, "clients-done");
                } else {
                    requestStop(ExitStatus.CLIENT_FAILED, "client failed: " + firstFailure);
                }
            }
        }
    }

    /** The port network clients connect to, or -1 if network clients are disabled. */
    public int getPort() {
        return parts.listener == null ? -1 : parts.listener.getPort();
    }

    /** The simulation this server runs. */
    public Simulation getSimulation() {
        return parts.simulation;
    }

    /** The configuration it was started with. */
    public ServerConfig getConfig() {
        return parts.config;
    }

    /** The server's log. */
    public ServerLog getLog() {
        return parts.log;
    }

    /**
     * Asks the server to stop with {@code status} and returns at once; the first request decides the
     * status. Safe from any thread, including the scheduler's and a client's.
     */
    public void requestStop(int status) {
        requestStop(status, "stopped");
    }

    private void requestStop(int status, String reason) {
        if (!stopping.compareAndSet(false, true)) {
            return;
        }
        stopReason = reason;
        requestedStatus = status;
        try {
            parts.helpers.start("shutdown", false, () -> shutDown(status));
            stopHandedAt = System.nanoTime();
        } catch (RuntimeException | Error e) {
            // No thread for the stop (out of memory, out of threads): the next request tries again,
            // instead of finding the server stopping and waiting for a stop that never began.
            stopReason = RUNNING;
            stopping.set(false);
            throw e;
        }
    }

    /** Stops the server on the calling thread, unless it is stopping already. */
    private void stopHere(int status, String reason) {
        if (stopping.compareAndSet(false, true)) {
            stopReason = reason;
            shutDown(status);
        }
    }

    /**
     * Stops the server because the process is exiting at a robot's call ({@link ExitCaller}): the run
     * failed, as if the robot had thrown, and says where it called; waits until the server has stopped.
     *
     * @param where the robot's call, as {@link ExitCaller#outsideTheSimulator()} gives it
     * @return the exit status, {@link ExitStatus#CLIENT_FAILED} unless the server was already stopping
     */
    public int stopForExitCall(String where) throws InterruptedException {
        parts.log.important("A robot called System.exit in " + where + ": the run stops, and counts as failed");
        requestStop(ExitStatus.CLIENT_FAILED, "client failed: called System.exit in " + where);
        return awaitExit();
    }

    /**
     * Stops the server and waits until it has; returns its status: 0, unless it was already stopping
     * with another, or a loaded client (2) or a simulation task (70) failed during the run.
     */
    public int stop() throws InterruptedException {
        requestStop(ExitStatus.OK);
        return awaitExit();
    }

    /** Waits until the server has stopped; returns the exit status. */
    public int awaitExit() throws InterruptedException {
        while (!exited.await(STOP_BEGINS_NANOS, TimeUnit.NANOSECONDS)) {
            takeOverLostStop();
        }
        return exitStatus;
    }

    /** Waits at most {@code timeout}; the exit status if the server stopped by then. */
    public OptionalInt awaitExit(long timeout, TimeUnit unit) throws InterruptedException {
        long left = unit.toNanos(timeout);
        while (left > 0) {
            long slice = Math.min(left, STOP_BEGINS_NANOS);
            long before = System.nanoTime();
            if (exited.await(slice, TimeUnit.NANOSECONDS)) {
                break;
            }
            takeOverLostStop();
            left -= System.nanoTime() - before;
        }
        return hasExited() ? OptionalInt.of(exitStatus) : OptionalInt.empty();
    }

    /**
     * A stop handed to a thread that has not begun it a second later (the thread ended first: out of
     * memory) would never come: a thread waiting for the server does it instead, so that whoever waits
     * for a run (a sweep's job) never waits for ever.
     */
    private void takeOverLostStop() {
        long handed = stopHandedAt;
        if (handed != 0 && !shutDownBegun.get() && System.nanoTime() - handed > STOP_BEGINS_NANOS) {
            shutDown(requestedStatus);
        }
    }

    /**
     * Why the server stopped (or is stopping): {@code max-simulation-time}, {@code clients-done},
     * {@code nobody-left} (a max-speed run whose clients and robots have all left),
     * {@code client failed: WHAT} (which replaces the others when a loaded client failed during the
     * run), {@code a simulation task failed: WHAT}, {@code the simulation failed: ERROR}, or
     * {@code stopped} (asked to: the window, a signal, a caller); {@code running} before that.
     */
    public String getStopReason() {
        return stopReason;
    }

    /** Whether the server has stopped. */
    public boolean hasExited() {
        return exited.getCount() == 0;
    }

    /**
     * Closes everything, in the order that lets clients see an orderly end and the log record it. A
     * step that fails (out of memory: a robot filled the heap) does not keep the others from being
     * tried, and the server counts as stopped in the end whatever failed: a stop that hung half way
     * would keep whoever waits for it (a sweep's job) waiting for ever, and the run's memory with it.
     */
    private void shutDown(int status) {
        if (!shutDownBegun.compareAndSet(false, true)) {
            return;
        }
        stopping.set(true);
        exitStatus = status;
        try {
            List<Runnable> steps = List.of(
                    () -> exitStatus = finalStatus(status),
                    // First, so that no client waiting its turn is started while the rest of the stop goes on.
                    parts.launcher::callOffWaiting,
                    () -> {
                        if (parts.listener != null) {
                            parts.listener.close();
                        }
                    },
                    // The scheduler stops first and the view closes while the clients are still connected,
                    // so the picture written at exit shows the robots where the run left them.
                    parts.simulation::shutdown,
                    this::joinScheduler,
                    this::closeRecordsAndView,
                    () -> parts.registry.closeAll("the server is shutting down"),
                    this::endClientThreads);
            Throwable failed = null;
            for (Runnable step : steps) {
                Throwable t = attempt(step);
                failed = failed != null ? failed : t;
            }
            if (failed != null) {
                Throwable first = failed;
                exitStatus = ExitStatus.FATAL_ERROR;
                attempt(() -> stopReason = stopReason + "; the stop failed: " + first);
                attempt(() -> parts.log.important("The stop failed in part: " + first));
            }
            attempt(() -> {
                Runtime rt = Runtime.getRuntime();
                parts.log.raw("  Total Memory used by JVM: " + rt.totalMemory());
                parts.log.raw("  Free  Memory:             " + rt.freeMemory());
            });
            attempt(parts.log::close);
        } finally {
            exited.countDown();
        }
    }

    /** Runs one step of the stop; returns what it threw instead of throwing it, or null. */
    private static Throwable attempt(Runnable step) {
        try {
            step.run();
            return null;
        } catch (RuntimeException | Error e) {
            return e;
        }
    }

    /**
     * The exit status of a stop asked for with {@code status}, with the log line that says why it
     * differs: a run that went on past a failure did not go as asked, whatever ended it.
     */
    private int finalStatus(int status) {
        ServerLog log = parts.log;
        String taskFailure = parts.simulation.getTaskFailure();
        String clientFailure = parts.launcher.firstFailure();
        if (status == ExitStatus.OK && taskFailure != null) {
            // The simulation went on past a defect of its own: its events may be wrong, and a sweep
            // must not average them in as a run that went as asked.
            log.important("The run ended (" + stopReason + ") after a simulation task failed");
            status = ExitStatus.FATAL_ERROR;
            stopReason = "a simulation task failed: " + taskFailure;
        } else if (status == ExitStatus.OK && clientFailure != null) {
            // A client that failed did not stop the others, but the run did not go as asked: its
            // status says so whatever ended it (maxSimulationTime, the last robot leaving).
            log.important("The run ended (" + stopReason + ") after a loaded client failed");
            status = ExitStatus.CLIENT_FAILED;
            stopReason = "client failed: " + clientFailure;
        }
        log.important("Shutting down simulator" + (status == ExitStatus.OK ? "" : " (exit status " + status + ")"));
        return status;
    }

    /** Finishes the records, then the view; a run whose output is not whole says so and exits with its status. */
    private void closeRecordsAndView() {
        parts.records.close();
        List<String> outputFailures = new ArrayList<>(parts.records.failures());
        closeView(outputFailures);
        for (String failure : outputFailures) {
            parts.log.important("The run's output is not whole: " + failure);
        }
        if (!outputFailures.isEmpty() && exitStatus == ExitStatus.OK) {
            exitStatus = ExitStatus.OUTPUT_FAILED;
            parts.log.important("Exit status " + ExitStatus.OUTPUT_FAILED + " (the run's output could not be written)");
        }
    }

    /**
     * Waits for the scheduler thread to end and for any other thread to finish the task it was running;
     * a thread that will not (a robot's handler that never returns) is ended, with a log line.
     */
    private void joinScheduler() {
        if (Thread.currentThread() == scheduler) {
            return;
        }
        Scheduler tasks = parts.simulation.getScheduler();
        try {
            List<StuckThreads.Ended> stuck = new ArrayList<>(StuckThreads.end(List.of(scheduler), GRACE_MILLIS));
            // A robot's handler that called System.exit holds the task until this stop is over.
            boolean exiting = scheduler.isAlive() && ExitCaller.isExiting(scheduler.getStackTrace());
            if (!tasks.awaitIdle(stuck.isEmpty() && !exiting ? GRACE_MILLIS : 0)) {
                Thread holder = tasks.runningTasks();
                if (holder != null && holder != Thread.currentThread() && holder != scheduler) {
                    stuck.addAll(StuckThreads.end(List.of(holder), 0));
                    tasks.awaitIdle(StuckThreads.AFTER_EACH_STEP_MILLIS);
                }
            }
            for (StuckThreads.Ended t : stuck) {
                parts.log.important("The simulation's task did not end when the run stopped: " + t);
                noteIfLeftRunning(t);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Waits for the loaded clients' threads (and the threads they started) to end now that their
     * sessions are closed; those that will not are ended, with a log line.
     */
    private void endClientThreads() {
        try {
            for (StuckThreads.Ended t : StuckThreads.end(parts.launcher.threads(), GRACE_MILLIS)) {
                parts.log.important("A loaded client's thread did not end with the run: " + t);
                noteIfLeftRunning(t);
            }
            // A thread a robot started (a timer, a worker) would otherwise run on through every later
            // run of a sweep's process; it gets the same grace, then the same end.
            for (StuckThreads.Ended t : StuckThreads.end(parts.launcher.startedByClients(scheduler), GRACE_MILLIS)) {
                parts.log.important("A thread a loaded client started did not end with the run: " + t);
                noteIfLeftRunning(t);
            }
            parts.launcher.releaseThreads();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void noteIfLeftRunning(StuckThreads.Ended t) {
        if (t.stillRunning()) {
            leftRunning.add(t.thread());
        }
    }

    /**
     * The threads of the run's robots that could not be ended when it stopped, each as "thread "NAME"
     * in CLASS.METHOD(FILE:LINE)": they keep computing in this process. Empty for a run that has not
     * stopped, or left none.
     */
    public List<String> threadsLeftRunning() {
        return List.copyOf(leftRunning);
    }

    /** Closes the view; a picture it could not write is added to {@code outputFailures}. */
    private void closeView(List<String> outputFailures) {
        try {
            view.close();
        } catch (IOException e) {
            outputFailures.add(e.getMessage());
        } catch (Exception e) {
            parts.log.log("closing the view failed: " + LoadedClient.describe(e));
        }
    }
}
