package rp1.spark;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.jar.JarOutputStream;
import java.util.zip.ZipEntry;
import java.util.stream.Stream;

import org.apache.spark.api.java.JavaSparkContext;

import rp1.simulator.batch.Batch;
import rp1.simulator.batch.RunEngine;
import rp1.simulator.batch.RunReport;
import rp1.simulator.batch.SweepException;
import rp1.simulator.batch.SweepRun;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ResourceLocator;
import rp1.simulator.launch.ExitStatus;

/**
 * A sweep's runs as Spark tasks, on the driver's side: each run is a job of one task
 * ({@link RunTask}) submitted from the sweep's thread for it, so that its files come back and its row
 * is written as soon as it ends, and a run lost with its executor is retried by Spark alone. The
 * robot's classes go to every executor with the job ({@code SparkContext.addFile}, a directory
 * packed as a jar first); the floor plans' text goes in each task.
 */
final class SparkRuns implements RunEngine {
    /** Beside a run's files on the driver: the files that stayed on the executor, too large to bring back. */
    static final String NOT_KEPT = "not-kept.txt";
    /** Beside a run's files on the driver: the executor's host the run went to last. */
    static final String EXECUTOR = "executor.txt";

    private final JavaSparkContext spark;
    private final double timeoutSeconds;
    private final Set<String> keep;
    private final LocalRun local;
    private final Map<String, String> planTexts;
    private final List<String> robotJars;
    private volatile boolean stopping;
    /** The names of the files the runs left, brought back or not: for the names --keep gave that none left. */
    private final Set<String> seen = ConcurrentHashMap.newKeySet();

    private SparkRuns(JavaSparkContext spark, double timeoutSeconds, Set<String> keep, LocalRun local,
                      Map<String, String> planTexts, List<String> robotJars) {
        this.spark = spark;
        this.timeoutSeconds = timeoutSeconds;
        this.keep = Set.copyOf(keep);
        this.local = local;
        this.planTexts = planTexts;
        this.robotJars = robotJars;
    }

    /**
     * The engine for {@code batch} on {@code spark}: ships the robot's classes and reads the plans.
     *
     * @param workingDirectory where the plans were found, as the sweep found them
     */
    static SparkRuns open(JavaSparkContext spark, Batch batch, Set<String> keep, LocalRun local, Path workingDirectory)
            throws SweepException {
        ResourceLocator locator = new ResourceLocator(workingDirectory, SparkRuns.class.getClassLoader());
        Map<String, String> planTexts = new LinkedHashMap<>();
        try {
            for (String plan : batch.plans().keySet()) {
                String text = locator.plan(plan).text;
                if (Batch.readsAnImage(plan, text)) {
                    // Only the plan's text goes in a task: the image it names would be missing there.
                    throw new SweepException("--plans " + plan + ": a plan whose walls come from a map image cannot"
                            + " go to a cluster yet (the image is not sent with the runs); run this sweep without"
                            + " --master");
                }
                planTexts.put(plan, text);
            }
        } catch (ConfigException e) {
            throw new SweepException(e.getMessage());
        }
        List<String> jars = new ArrayList<>();
        try {
            Path shipped = Files.createTempDirectory("rp1-robot-");
            shipped.toFile().deleteOnExit();
            List<Path> classPath = batch.robotClassPath();
            for (int i = 0; i < classPath.size(); i++) {
                Path entry = classPath.get(i);
                Path jar = shipped.resolve("robot-" + i + "-" + entry.getFileName() + (Files.isDirectory(entry) ? ".jar" : ""));
                if (Files.isDirectory(entry)) {
                    pack(entry, jar);
                } else {
                    Files.copy(entry, jar);
                }
                jar.toFile().deleteOnExit();
                spark.addFile(jar.toString());
                jars.add(jar.getFileName().toString());
            }
        } catch (IOException e) {
            throw new SweepException("-cp: cannot ship the robot's classes to the cluster: " + e.getMessage());
        }
        return new SparkRuns(spark, batch.options().timeoutSeconds, keep, local, planTexts, jars);
    }

    /** The files under {@code dir} as a jar, for executors that do not share the driver's folders. */
    private static void pack(Path dir, Path jar) throws IOException {
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar)); Stream<Path> all = Files.walk(dir)) {
            for (Path f : (Iterable<Path>) all.sorted()::iterator) {
                if (Files.isRegularFile(f)) {
                    out.putNextEntry(new ZipEntry(dir.relativize(f).toString().replace('\\', '/')));
                    Files.copy(f, out);
                    out.closeEntry();
                }
            }
        }
    }

    @Override
    public Ran run(Batch.Run run) throws IOException {
        Path dir = run.dir().toAbsolutePath();
        String name = dir.getFileName().toString();
        RunTask task = new RunTask(name, Files.readString(dir.resolve(SweepRun.PROPERTIES)), dir.toString(), run.plan(),
                planTexts.get(run.plan()), robotJars, keep, timeoutSeconds, local);
        // A group per run, which the job's thread is in: cancelling all of them stops the sweep.
        spark.setJobGroup("rp1-run-" + UUID.randomUUID(), "rp1 run " + name, true);
        RunFiles files;
        try {
            files = spark.parallelize(List.of(task), 1).map(RunTask::call).collect().get(0);
        } catch (Exception e) {
            if (stopping) {
                return new Ran(RunReport.failed("stopped", ExitStatus.OK), List.of());
            }
            String why = String.valueOf(e.getMessage()).lines().findFirst().orElse(e.toString());
            return new Ran(RunReport.failed(RunReport.LOST_BY_CLUSTER + why, ExitStatus.STARTUP_FAILED),
                    List.of());
        }
        for (Map.Entry<String, byte[]> f : files.files.entrySet()) {
            Files.write(dir.resolve(f.getKey()), f.getValue());
        }
        seen.addAll(files.files.keySet());
        seen.addAll(files.leftOut.keySet());
        Files.write(dir.resolve(EXECUTOR), (files.host + "\n").getBytes(StandardCharsets.UTF_8));
        Path notKept = dir.resolve(NOT_KEPT);
        if (files.leftOut.isEmpty()) {
            Files.deleteIfExists(notKept);
        } else {
            try (OutputStream out = Files.newOutputStream(notKept)) {
                out.write(("# Larger than " + (RunTask.SMALL_BYTES >> 20) + " MB, left on the executor (--keep NAME"
                        + " brings them back):\n" + leftOutLines(files.leftOut)).getBytes(StandardCharsets.UTF_8));
            }
        }
        try {
            return new Ran(RunReport.read(dir), files.trails());
        } catch (IOException e) {
            return new Ran(RunReport.failed("the run came back without results: " + e.getMessage(),
                    ExitStatus.STARTUP_FAILED), files.trails());
        }
    }

    /** A line per file left on the executor: "NAME (N bytes)". */
    private static String leftOutLines(Map<String, Long> leftOut) {
        StringBuilder lines = new StringBuilder();
        leftOut.forEach((name, size) -> lines.append(name).append(" (").append(size).append(" bytes)\n"));
        return lines.toString();
    }

    /** Which names --keep gave that no run left a file of (a mistyped name brings nothing back), or null. */
    @Override
    public String note() {
        List<String> missing = notLeft(keep, seen);
        return missing.isEmpty() ? null : "--keep " + String.join(",", missing) + ": no run left a file of that name"
                + " (a run leaves " + String.join(", ", seen.stream().sorted().toList()) + ")";
    }

    /** The names of {@code keep} (but "all") that are not among {@code left}, in order. */
    static List<String> notLeft(Set<String> keep, Set<String> left) {
        return keep.stream().filter(k -> !k.equals(RunTask.ALL) && !left.contains(k)).sorted().toList();
    }

    @Override
    public void stopAll() {
        stopping = true;
        // Cancelled tasks and executors shutting down are logged by Spark as errors with their stack
        // traces, after the sweep has said how it stopped and how to go on; they are not the user's.
        spark.setLogLevel("OFF");
        spark.cancelAllJobs();
    }
}
