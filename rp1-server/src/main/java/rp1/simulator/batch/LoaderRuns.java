package rp1.simulator.batch;

import java.io.IOException;
import java.util.ArrayList;
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
 *
 * <p>The runs also share the process's heap. When they leave it short ({@link MemoryGuard}: a robot
 * that keeps memory without end), the runs going are stopped and carried out again in processes of
 * their own, and so is every run after them; a run that failed here of an {@link OutOfMemoryError}
 * (which a run beside it may have caused) is carried out again in a process of its own. Each gets the
 * row it would have had in a process of its own from the start, and the sweep's last line says so.
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
    /**
     * Makes the engine for runs that cannot go on in this process (a run left a thread running, or
     * memory ran short); null: none (a Spark task's one run), and they go on here.
     */
    private final Supplier<RunEngine> elsewhere;
    /** That engine, once made. */
    private RunEngine other;
    /** Whether every run from now on goes to {@link #other}. */
    private boolean allElsewhere;
    /** The lines that say which runs went elsewhere, and why. */
    private final List<String> elsewhereNotes = new ArrayList<>();
    /** Looks out for the heap running short while runs go here; made with the first run. */
    private MemoryGuard<LoaderRuns> memory;
    /** The runs going here that were stopped because memory ran short, to be carried out again elsewhere. */
    private final Set<RunningServer> stoppedShort = ConcurrentHashMap.newKeySet();
    /** Whether memory ran short: a run that begins here after that is stopped at once, to go elsewhere. */
    private volatile boolean memoryShort;
    private boolean closed;

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
     * @param elsewhere  makes the engine for the runs that cannot go on in this process (null: they go
     *                   on here)
     */
    LoaderRuns(List<String> robotClasses, ClassLoader parent, double timeoutSeconds, ParsedPlans plans,
               Supplier<RunEngine> elsewhere) {
        this.classes = RunClassLoader.source(robotClasses, parent);
        this.timeoutSeconds = timeoutSeconds;
        this.plans = plans;
        this.elsewhere = elsewhere;
    }

    /**
     * The first of the robot's classes that calls System.exit or the like, as "CLASS calls
     * System.exit", which would end every run in this process at once; empty if none does.
     */
    Optional<String> exitCall() {
        return classes.exitCall();
    }

    /** The engine every run now goes to instead of this process, or null while they go here. */
    private synchronized RunEngine instead() {
        return allElsewhere ? other : null;
    }

    /** The engine for runs that go elsewhere, made if need be; null if there is no elsewhere (or closed). */
    private synchronized RunEngine other() {
        if (other == null && elsewhere != null && !closed) {
            other = elsewhere.get();
            if (stopping) {
                other.stopAll();
            }
        }
        return other;
    }

    /** From now on every run goes elsewhere, if there is an elsewhere; {@code why} says so on the sweep's last line. */
    private synchronized void allElsewhere(String why) {
        if (allElsewhere || other() == null) {
            return;
        }
        allElsewhere = true;
        elsewhereNotes.add(why);
    }

    /** The run left threads running: the runs after it go elsewhere. */
    private void leftRunning(Batch.Run run, List<String> threads) {
        allElsewhere("the runs after " + run.dir().getFileName() + " went in processes of their own: it left "
                + threads.get(0) + " running, which could not be stopped");
    }

    /**
     * The heap ran short ({@link MemoryGuard}, on its thread): the runs going here stop, to be carried
     * out again elsewhere with every run after them.
     */
    synchronized void memoryShort() {
        letGoOfReserve();
        if (allElsewhere || other() == null) {
            return;
        }
        memoryShort = true;
        allElsewhere("the runs from then on went in processes of their own, those going then again: the sweep's"
                + " process ran short of memory (a robot that keeps memory without end starves the runs beside it)");
        for (RunningServer s : running) {
            stoppedShort.add(s);
            s.requestStop(ExitStatus.OK);
        }
    }

    /**
     * Whether a run carried out here is to be carried out again elsewhere: it was stopped because memory
     * ran short, or it failed of running out of memory, which a run beside it may have caused (not if
     * the sweep is being interrupted: --resume runs it again).
     */
    private boolean toBeRedone(RanHere here) {
        return !stopping && (here.stoppedShort() || here.ran().report().endReason().contains(OutOfMemoryError.class.getName()))
                && other() != null;
    }

    /** Gives the runs' stops the memory the guard set aside for them. */
    private synchronized void letGoOfReserve() {
        if (memory != null) {
            memory.letGoOfReserve();
        }
    }

    /** Starts the guard with the first run (none where no run can go elsewhere). */
    private synchronized void guardMemory() {
        if (memory == null && elsewhere != null && !closed) {
            memory = new MemoryGuard<>(this, LoaderRuns::memoryShort);
        }
    }

    /** Whether a run is going in this process. */
    boolean anyRunning() {
        return !running.isEmpty();
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
        RunEngine instead = instead();
        if (instead != null) {
            return instead.run(run);
        }
        guardMemory();
        RanHere here;
        try {
            here = runHere(run);
        } catch (OutOfMemoryError e) {
            // This job's own thread found the heap full (a collector that lets it fill between two of
            // the guard's looks): as if the guard had seen it, with this run among those going then.
            if (stopping || elsewhere == null) {
                throw e;
            }
            memoryShort();
            here = new RanHere(null, true);
        }
        if (!toBeRedone(here)) {
            return here.ran();
        }
        RunEngine redo;
        synchronized (this) {
            elsewhereNotes.add(run.dir().getFileName() + " was carried out again in a process of its own: "
                    + (here.stoppedShort() ? "memory ran short while it went"
                    : "it ran out of memory here, which a run beside it may have caused"));
            redo = other();
        }
        RunFolder.forgetOutcome(run);
        return redo.run(run);
    }

    /** A run carried out here, and whether it was stopped because memory ran short. */
    private record RanHere(Ran ran, boolean stoppedShort) {
    }

    private RanHere runHere(Batch.Run run) throws IOException, InterruptedException {
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
                } else if (memoryShort) {
                    // Began as memory ran short, too late to be among the runs stopped.
                    stoppedShort.add(server);
                    server.requestStop(ExitStatus.OK);
                }
            }, timeoutSeconds);
            if (mine.get() != null && !mine.get().threadsLeftRunning().isEmpty()) {
                leftRunning(run, mine.get().threadsLeftRunning());
            }
            RunningServer server = mine.get();
            return new RanHere(new Ran(report, here.trails()), server != null && stoppedShort.remove(server));
        } catch (Error e) {
            // This thread failed while the run went (out of memory): the run must not go on unwatched.
            RunningServer server = mine.get();
            if (server != null) {
                try {
                    letGoOfReserve();
                    server.requestStop(ExitStatus.OK);
                } catch (Error stillShort) {
                    // No thread for its stop: its scheduler, short of memory too, stops it on its own thread.
                }
            }
            throw e;
        } finally {
            thread.setContextClassLoader(before);
            if (mine.get() != null) {
                running.remove(mine.get());
                // Already gone when the run returned its report; not if this thread failed: the run,
                // and the memory its robot keeps, must not stay reachable from here.
                stoppedShort.remove(mine.get());
            }
            if (loader != shared) {
                loader.close();
            }
        }
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (memory != null) {
            memory.close();
        }
        if (other != null) {
            other.close();
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
        List<String> lines = new ArrayList<>();
        if (sharing != null) {
            lines.add(sharing.note());
        }
        lines.addAll(elsewhereNotes);
        return lines.isEmpty() ? null : String.join("; ", lines);
    }

    @Override
    public boolean firstRunWarmsUp() {
        return true;
    }

    @Override
    public void stopAll() {
        stopping = true;
        running.forEach(s -> s.requestStop(ExitStatus.OK));
        RunEngine made;
        synchronized (this) {
            made = other;
        }
        if (made != null) {
            made.stopAll();
        }
    }

    @Override
    public boolean runsEndWithinTheirTimeout() {
        return true;
    }
}
