package rp1.simulator.batch;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;

import rp1.planparser.ParsedPlans;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.RunningServer;

/**
 * Runs in the sweep's own process ({@code --isolation loader}): each with the robot's classes as a
 * process of its own would have them and a server, simulation and world of its own, so that the
 * process is started and warmed once for all of them. A run is then a function of its properties,
 * plan and seed as it is in a process of its own, as long as the robot keeps its state in its objects
 * and its classes' statics, starts no threads that outlive the run and does not call
 * {@code System.exit} (docs/guide.md says when to use {@code --isolation process}).
 *
 * <p>Where a class of the robot's can keep state in a static field, each run loads the robot's
 * classes anew ({@link RunClassLoader}), so that its statics start afresh. Where none can
 * ({@link StaticState}), a class is the same in every run, and the runs after the first share one
 * loader: the robot's classes are defined, verified and linked once more, and its code is compiled
 * once instead of being interpreted again in every run.
 *
 * <p>A run whose robot holds a thread that cannot be ended when the run stops (a handler looping
 * around {@code catch (Throwable t)}: {@link RunningServer#threadsLeftRunning}) leaves it computing in
 * this process, and every later run like it would add one. So a sweep's runs after it are carried out
 * in processes of their own, as {@code --isolation process} would, with the same results; the sweep's
 * last line says so.
 */
final class LoaderRuns implements RunEngine {
    private final RunClassLoader.Source classes;
    private final double timeoutSeconds;
    /** Each floor plan parsed once, a copy for each run. */
    private final ParsedPlans plans;
    /** The runs' client starters and stops, on threads kept from run to run. */
    private final KeptThreads helpers = new KeptThreads();
    private final Set<RunningServer> running = ConcurrentHashMap.newKeySet();
    private volatile boolean stopping;
    /** Makes the engine the runs go on with once a run left a thread running; null: none (a Spark task's one run). */
    private final Supplier<RunEngine> afterStuck;
    /** That engine, once made; and the line that says why. */
    private RunEngine instead;
    private String insteadNote;

    /**
     * Whether the runs share one loader, worked out when a second run starts: an engine that carries
     * out one run (a Spark task's) has nothing to share, and a sweep's first run, which goes alone, is
     * not kept waiting for the robot's class path to be looked through.
     */
    private Sharing sharing;
    private boolean started;

    /** The loader all runs share (null if each run has one of its own), and what the user is told. */
    private record Sharing(RunClassLoader loader, String note) {
    }

    /**
     * @param plans      the floor plans parsed for the sweep, of which each run gets a copy
     * @param afterStuck makes the engine for the runs after one that left a thread running (null: go
     *                   on in this process)
     */
    LoaderRuns(List<String> robotClasses, ClassLoader parent, double timeoutSeconds, ParsedPlans plans,
               Supplier<RunEngine> afterStuck) {
        this.classes = RunClassLoader.source(robotClasses, parent);
        this.timeoutSeconds = timeoutSeconds;
        this.plans = plans;
        this.afterStuck = afterStuck;
    }

    /**
     * The first of the robot's classes that calls System.exit or the like, as "CLASS calls
     * System.exit", which would end every run in this process at once; empty if none does.
     */
    Optional<String> exitCall() {
        return classes.exitCall();
    }

    /** The engine the runs go on with instead of this process, or null while they stay here. */
    private synchronized RunEngine instead() {
        return instead;
    }

    /** The run left threads running: the runs after it go elsewhere, if there is an elsewhere. */
    private synchronized void leftRunning(Batch.Run run, List<String> threads) {
        if (instead != null || afterStuck == null) {
            return;
        }
        instead = afterStuck.get();
        insteadNote = "the runs after " + run.dir().getFileName() + " went in processes of their own: it left "
                + threads.get(0) + " running, which could not be stopped";
        if (stopping) {
            instead.stopAll();
        }
    }

    /** The loader this run shares with others, or null if it has one of its own. */
    private synchronized RunClassLoader sharedLoader() {
        if (!started) {
            started = true;
            return null;
        }
        return sharing().loader();
    }

    private synchronized Sharing sharing() {
        if (sharing == null) {
            Optional<String> state = classes.staticState();
            sharing = state.isEmpty()
                    ? new Sharing(classes.newLoader(), "the runs shared the robot's classes: none keeps state in a static field")
                    : new Sharing(null, "each run loaded the robot's classes anew: " + state.get()
                            + " can keep state in a static field");
        }
        return sharing;
    }

    @Override
    public Ran run(Batch.Run run) throws IOException, InterruptedException {
        RunEngine elsewhere = instead();
        if (elsewhere != null) {
            return elsewhere.run(run);
        }
        Thread thread = Thread.currentThread();
        ClassLoader before = thread.getContextClassLoader();
        AtomicReference<RunningServer> mine = new AtomicReference<>();
        RunClassLoader shared = sharedLoader();
        RunClassLoader loader = shared != null ? shared : classes.newLoader();
        try {
            // The robot's threads, and any library it uses that asks the context, see its own classes.
            thread.setContextClassLoader(loader);
            SweepRun here = new SweepRun(run.dir(), loader, plans, helpers);
            RunReport report = here.run(server -> {
                mine.set(server);
                running.add(server);
                if (stopping) {
                    server.requestStop(ExitStatus.OK);
                }
            }, timeoutSeconds);
            if (mine.get() != null && !mine.get().threadsLeftRunning().isEmpty()) {
                leftRunning(run, mine.get().threadsLeftRunning());
            }
            return new Ran(report, here.trails());
        } finally {
            thread.setContextClassLoader(before);
            if (mine.get() != null) {
                running.remove(mine.get());
            }
            if (loader != shared) {
                loader.close();
            }
        }
    }

    @Override
    public synchronized void close() {
        if (instead != null) {
            instead.close();
        }
        helpers.close();
        // The shared loader's classes stay usable (a loaded class needs no open jar); only its jars
        // and the loader's own resources are let go. The note stays for the sweep's last line.
        if (sharing != null && sharing.loader() != null) {
            try {
                sharing.loader().close();
            } catch (IOException e) {
                // A jar that will not close stays open until the loader is collected: the runs are over either way.
            }
        }
    }

    @Override
    public synchronized String note() {
        String shared = sharing == null ? null : sharing.note();
        return insteadNote == null ? shared : shared == null ? insteadNote : shared + "; " + insteadNote;
    }

    @Override
    public boolean firstRunWarmsUp() {
        return true;
    }

    @Override
    public void stopAll() {
        stopping = true;
        running.forEach(s -> s.requestStop(ExitStatus.OK));
        RunEngine elsewhere = instead();
        if (elsewhere != null) {
            elsewhere.stopAll();
        }
    }
}
