package rp1.spark;

import java.io.File;
import java.io.IOException;
import java.io.Serializable;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.apache.spark.SparkFiles;

import rp1.simulator.batch.PropertiesText;
import rp1.simulator.batch.RunEngine;
import rp1.simulator.batch.SweepRun;
import rp1.simulator.outcome.Trail;

/**
 * One run of a sweep as a Spark task: the run's {@code run.ini} as the driver wrote it, and what the
 * executor needs to carry it out on a machine that does not share the driver's folders. On the
 * executor ({@link #call()}) it runs in a folder of its own under the temporary folder, with the
 * run's output files named there instead of in the driver's {@code --out}, and comes back as
 * {@link RunFiles}. A run that fails by itself still returns (its report says why), so Spark does not
 * retry it; only a lost executor or an error of the executor's own makes the task fail and be retried.
 */
final class RunTask implements Serializable {
    private static final long serialVersionUID = 1L;
    /** The properties that name the run's output files. */
    private static final List<String> OUTPUTS = List.of("logFileName", "recordFileName", "eventLogFileName",
            "snapshotFileName");
    /** Files up to this size come back whatever {@code --keep} says. */
    static final long SMALL_BYTES = 4L << 20;
    /** The --keep name that brings back every file. */
    static final String ALL = "all";

    /** The run's folder name, for the temporary folder's name. */
    private final String name;
    private final String propertiesText;
    /** The run's folder on the driver, as {@code run.ini} names its output files. */
    private final String driverDir;
    /** The floor plan's file name and text, written beside the run (the executor may not have the file). */
    private final String planName;
    private final String planText;
    /** The file names of the robot's classes shipped with the job (SparkContext.addFile). */
    private final List<String> robotJars;
    /** File names that come back whatever their size; "all" for every file. */
    private final Set<String> keep;
    private final double timeoutSeconds;
    private final LocalRun local;

    RunTask(String name, String propertiesText, String driverDir, String planName, String planText,
            List<String> robotJars, Set<String> keep, double timeoutSeconds, LocalRun local) {
        this.name = name;
        this.propertiesText = propertiesText;
        this.driverDir = driverDir;
        this.planName = planName;
        this.planText = planText;
        this.robotJars = List.copyOf(robotJars);
        this.keep = Set.copyOf(keep);
        this.timeoutSeconds = timeoutSeconds;
        this.local = local;
    }

    /** Carries the run out here, on the executor, and gathers its files. */
    RunFiles call() throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory("rp1-run-" + name + "-");
        try {
            Path plan = dir.resolve("plan-" + Paths.get(planName).getFileName());
            Files.write(plan, planText.getBytes(StandardCharsets.UTF_8));
            Files.write(dir.resolve(SweepRun.PROPERTIES), relocated(propertiesText, driverDir, dir, plan)
                    .getBytes(StandardCharsets.UTF_8));
            RunEngine.Ran ran = local.run(dir, robotClassPath(), timeoutSeconds);
            ran.report().write(dir);
            Files.delete(dir.resolve(SweepRun.PROPERTIES));
            Files.delete(plan);
            return gather(dir, ran.trails());
        } finally {
            delete(dir);
        }
    }

    /**
     * The run's properties as they take effect, with its output files in {@code dir} instead of the
     * driver's {@code driverDir}, and the plan's copy {@code plan} as its floor plan. Read and written
     * as properties, key by key: run.ini's values are escaped (a path with a drive letter's colon, or
     * an accented letter, does not read as it is written), so the text cannot be rewritten as text.
     */
    static String relocated(String propertiesText, String driverDir, Path dir, Path plan) {
        Properties p = new Properties();
        try {
            p.load(new StringReader(propertiesText));
        } catch (IOException e) {
            throw new UncheckedIOException("a string cannot fail to be read", e);
        }
        Map<String, String> entries = new TreeMap<>();
        p.stringPropertyNames().forEach(k -> entries.put(k, p.getProperty(k)));
        for (String key : OUTPUTS) {
            String file = entries.get(key);
            if (file != null && file.startsWith(driverDir + File.separator)) {
                entries.put(key, dir + file.substring(driverDir.length()));
            }
        }
        entries.put("floorPlanFileName", plan.toString());
        return "# rp1-spark: the run's properties, its files here and the plan's text beside it\n"
                + PropertiesText.of(entries);
    }

    /** Where this executor put the robot's classes that came with the job. */
    private List<Path> robotClassPath() {
        List<Path> paths = new ArrayList<>();
        for (String jar : robotJars) {
            paths.add(Paths.get(SparkFiles.get(jar)));
        }
        return paths;
    }

    private RunFiles gather(Path dir, List<Trail> trails) throws IOException {
        Map<String, byte[]> files = new LinkedHashMap<>();
        Map<String, Long> leftOut = new LinkedHashMap<>();
        try (Stream<Path> list = Files.list(dir)) {
            for (Path f : (Iterable<Path>) list.sorted()::iterator) {
                if (!Files.isRegularFile(f)) {
                    continue;
                }
                String n = f.getFileName().toString();
                long size = Files.size(f);
                if (size <= SMALL_BYTES || keep.contains(n) || keep.contains(ALL)) {
                    files.put(n, Files.readAllBytes(f));
                } else {
                    leftOut.put(n, size);
                }
            }
        }
        return new RunFiles(files, leftOut, InetAddress.getLocalHost().getHostName(), trails);
    }

    private static void delete(Path dir) {
        try (Stream<Path> all = Files.walk(dir)) {
            all.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        } catch (IOException | UncheckedIOException e) {
            // A temporary folder left behind costs a little disk, not the run.
        }
    }
}
