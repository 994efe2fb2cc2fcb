package rp1.spark;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import rp1.simulator.batch.RunEngine;
import rp1.simulator.batch.RunReport;
import rp1.simulator.batch.Trail;
import rp1.simulator.batch.TrailFile;
import rp1.simulator.batch.SweepRun;
import rp1.simulator.launch.JavaCommand;

/**
 * A run in a Java process of its own on the executor's machine ({@code --isolation process}), as the
 * sweep runs one on its own machine: {@code java rp1.simulator.batch.SweepRun DIR [-cp ROBOT]} with
 * the executor's Java and class path, stopped as Ctrl-C would stop it if it outlasts the timeout or
 * the task is cancelled.
 */
final class ProcessRun implements LocalRun {
    private static final long serialVersionUID = 1L;
    /** What the run's process printed, in its folder (the driver's report of a crash quotes it). */
    static final String OUTPUT = "output.txt";
    /** How long a run asked to stop may take to close its files before it is killed. */
    private static final long STOP_GRACE_SECONDS = 10;

    @Override
    public RunEngine.Ran run(Path dir, List<Path> robotClassPath, double timeoutSeconds) throws IOException, InterruptedException {
        List<String> args = new ArrayList<>(List.of(dir.toString()));
        if (!robotClassPath.isEmpty()) {
            args.add("-cp");
            args.add(robotClassPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)));
        }
        Process p = new ProcessBuilder(JavaCommand.of(List.of(), SweepRun.class.getName(), args.toArray(new String[0])))
                .redirectErrorStream(true).redirectOutput(dir.resolve(OUTPUT).toFile()).start();
        boolean ended;
        try {
            ended = p.waitFor((long) (timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            // The task was cancelled (the sweep was interrupted): the run closes its files and goes.
            stop(p);
            throw e;
        }
        if (!ended) {
            stop(p);
            return new RunEngine.Ran(RunReport.failed(String.format(Locale.ROOT, "timeout: still running after %.0f s"
                    + " of wall time", timeoutSeconds), RunReport.TIMED_OUT), List.of());
        }
        List<Trail> trails;
        try {
            trails = TrailFile.read(dir);
        } catch (IOException e) {
            trails = List.of();
        }
        return new RunEngine.Ran(RunReport.ofProcess(dir, dir.resolve(OUTPUT), p.exitValue()), trails);
    }

    private static void stop(Process p) throws InterruptedException {
        p.destroy();
        if (!p.waitFor(STOP_GRACE_SECONDS, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            p.waitFor();
        }
    }
}
