package rp1.simulator.batch;

import java.io.IOException;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicReference;

import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.RunningServer;

/**
 * Runs in the sweep's own process ({@code --isolation loader}): each with a class loader of its own
 * for the robot's classes ({@link RunClassLoader}) and a server, simulation and world of its own, so
 * that the process is started and warmed once for all of them. A run is then a function of its
 * properties, plan and seed as it is in a process of its own, as long as the robot keeps its state
 * in its objects and its classes' statics, starts no threads that outlive the run and does not call
 * {@code System.exit} (docs/guide.md says when to use {@code --isolation process}).
 */
final class LoaderRuns implements RunEngine {
    private final RunClassLoader.Source classes;
    private final double timeoutSeconds;
    private final Set<RunningServer> running = ConcurrentHashMap.newKeySet();
    private volatile boolean stopping;

    LoaderRuns(List<String> robotClasses, ClassLoader parent, double timeoutSeconds) {
        this.classes = RunClassLoader.source(robotClasses, parent);
        this.timeoutSeconds = timeoutSeconds;
    }

    @Override
    public Ran run(Batch.Run run) throws IOException, InterruptedException {
        Thread thread = Thread.currentThread();
        ClassLoader before = thread.getContextClassLoader();
        AtomicReference<RunningServer> mine = new AtomicReference<>();
        try (RunClassLoader loader = classes.newLoader()) {
            // The robot's threads, and any library it uses that asks the context, see its own classes.
            thread.setContextClassLoader(loader);
            SweepRun here = new SweepRun(run.dir(), loader);
            RunReport report = here.run(server -> {
                mine.set(server);
                running.add(server);
                if (stopping) {
                    server.requestStop(ExitStatus.OK);
                }
            }, timeoutSeconds);
            return new Ran(report, here.trails());
        } finally {
            thread.setContextClassLoader(before);
            if (mine.get() != null) {
                running.remove(mine.get());
            }
        }
    }

    @Override
    public boolean firstRunWarmsUp() {
        return true;
    }

    @Override
    public void stopAll() {
        stopping = true;
        running.forEach(s -> s.requestStop(ExitStatus.OK));
    }
}
