package rp1.simulator.batch;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Collectors;

import rp1.simulator.launch.JavaCommand;

/**
 * Runs each in a Java process of its own ({@code --isolation process}): {@link SweepRun} started as
 * {@code java rp1.simulator.batch.SweepRun DIR}, stopped if it takes longer than the timeout. For
 * robots that cannot share a process: static state shared between instances, {@code System.exit},
 * threads of their own that outlive a run.
 */
final class ProcessRuns implements RunEngine {
    /** What the run's process printed. */
    static final String OUTPUT = "output.txt";
    /** How long a run that is asked to stop may take to close its files before it is killed. */
    static final long STOP_GRACE_SECONDS = 10;

    /**
     * A simulator's options, and the quick compiler only: a run computes for milliseconds, so the
     * optimizing compiler's work would never pay back, and costs more than the run (docs/performance.md).
     */
    static final List<String> RUN_JVM_OPTIONS = jvmOptions();

    private final double timeoutSeconds;
    /** The robot's classes ({@code -cp}), absolute, handed to each run's process. */
    private final List<Path> classPath;
    private final Set<Process> running = ConcurrentHashMap.newKeySet();
    private final String note;
    private volatile boolean stopping;

    ProcessRuns(double timeoutSeconds, List<Path> classPath) {
        this(timeoutSeconds, classPath, null);
    }

    /** @param note what the sweep's last line says of how the runs went, or null */
    ProcessRuns(double timeoutSeconds, List<Path> classPath, String note) {
        this.timeoutSeconds = timeoutSeconds;
        this.classPath = List.copyOf(classPath);
        this.note = note;
    }

    @Override
    public String note() {
        return note;
    }

    private static List<String> jvmOptions() {
        List<String> options = new ArrayList<>(JavaCommand.simulatorOptions());
        options.add(JavaCommand.QUICK_COMPILER);
        return List.copyOf(options);
    }

    /** The run's folder, and the robot's class path (-cp), for {@link SweepRun}'s command line. */
    private String[] arguments(Batch.Run run) {
        List<String> args = new ArrayList<>(List.of(run.dir().toAbsolutePath().toString()));
        if (!classPath.isEmpty()) {
            args.add("-cp");
            args.add(classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)));
        }
        return args.toArray(new String[0]);
    }

    @Override
    public Ran run(Batch.Run run) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(JavaCommand.of(RUN_JVM_OPTIONS, SweepRun.class.getName(), arguments(run)))
                .redirectErrorStream(true)
                .redirectOutput(run.dir().resolve(OUTPUT).toFile()).start();
        running.add(p);
        if (stopping) {
            p.destroy();
        }
        boolean ended;
        try {
            ended = p.waitFor((long) (timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            stop(p);
            throw e;
        } finally {
            running.remove(p);
        }
        if (!ended) {
            stop(p);
            return new Ran(RunReport.failed(String.format(Locale.ROOT, "timeout: still running after %.0f s of wall time",
                    timeoutSeconds), RunReport.TIMED_OUT), RunFolder.trails(run));
        }
        return new Ran(report(run.dir(), p.exitValue()), RunFolder.trails(run));
    }

    /**
     * Stops the runs going as Ctrl-C would (SIGTERM), so they close their recordings; a run still
     * going after a grace period is killed.
     */
    @Override
    public void stopAll() {
        stopping = true;
        running.forEach(Process::destroy);
        Thread killer = new Thread(() -> {
            try {
                Thread.sleep(TimeUnit.SECONDS.toMillis(STOP_GRACE_SECONDS));
            } catch (InterruptedException e) {
                return;
            }
            running.forEach(Process::destroyForcibly);
        }, "rp1-sweep-stop");
        killer.setDaemon(true);
        killer.start();
    }

    /**
     * Stops a run as Ctrl-C would, so that it closes its recording and event log (the rows worth
     * replaying are often these); forcibly if it has not stopped within a grace period.
     */
    private static void stop(Process p) throws InterruptedException {
        stop(p, STOP_GRACE_SECONDS);
    }

    /**
     * Stops {@code p} and the processes it started as Ctrl-C would (SIGTERM), forcibly if they are still
     * going {@code graceSeconds} later. Its children are asked too: a {@code --client} script that runs
     * the robot without {@code exec} left the robot running, its parent gone, after every run.
     */
    static void stop(Process p, long graceSeconds) throws InterruptedException {
        if (!p.isAlive()) {
            return;
        }
        // Taken first: once p has ended, the processes it started are no longer its descendants.
        List<ProcessHandle> started = p.descendants().toList();
        p.destroy();
        started.forEach(ProcessHandle::destroy);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(graceSeconds);
        if (!p.waitFor(graceSeconds, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            p.waitFor();
        }
        for (ProcessHandle h : started) {
            try {
                h.onExit().get(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (TimeoutException | ExecutionException e) {
                h.destroyForcibly();
            }
        }
    }

    private static RunReport report(Path dir, int status) {
        return RunReport.ofProcess(dir, dir.resolve(OUTPUT), status);
    }

    @Override
    public boolean runsEndWithinTheirTimeout() {
        return true;
    }
}
