package rp1demo.bench;

import java.io.File;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import rp1.simulator.launch.JavaCommand;

/**
 * {@code gradle bench} (this module's part, docs/performance.md): the wall time of 64 bumper runs of
 * 60 simulated seconds swept with {@code --jobs 2} in one process ({@code --isolation loader}), side
 * by side with one bumper run started as a process of its own ({@code java rp1.Server -p bumper.ini}),
 * and 8 runs with {@code --isolation process} for comparison, each JVM with the options the installed
 * {@code rp1} gives it, every one a fresh process, as a user would start it. The one run and the
 * sweep are timed in {@link #PAIRS} alternating pairs and compared pair by pair; the others are the
 * median of three tries. Prints figures and never fails on them.
 *
 * <p>The sweeps write their folders in the system's temporary folder, as a user's would go on a disk;
 * where there is a RAM disk ({@code /dev/shm}) each pair also times the sweep with its folder there. A
 * sweep creates some 450 files and folders where the one run creates one picture, and on a file system
 * that makes creating files slow for minutes after many were deleted (this project's machine: ext4
 * without a journal, docs/performance.md) the first figure moves with the disk's recent past; the
 * second is the simulator's alone. The cost of creating that many files in both places is printed too.
 */
public final class SweepBench {
    private static final int TRIES = 3;
    /**
     * Pairs of the one run and the 64-run sweep, timed alternately. With 8, the median ratio of one
     * build moved from 1.92 to 2.37 between sittings of the same hour on this project's shared
     * two-core machine (docs/performance.md); 16 halve that spread's effect for 10 s more.
     */
    private static final int PAIRS = 16;
    /** The options bin/rp1 starts a simulation's JVM with. */
    private static final List<String> SIMULATOR = JavaCommand.simulatorOptions();
    /** The options bin/rp1 starts a sweep's JVM with on this machine. */
    private static final List<String> QUICK = JavaCommand.sweepOptions(Runtime.getRuntime().availableProcessors());
    /** The same with both compilers (and the JVM's own number of compiler threads, which both need). */
    private static final List<String> BOTH_COMPILERS = QUICK.stream()
            .filter(o -> !o.equals(JavaCommand.QUICK_COMPILER) && !o.equals(JavaCommand.ONE_COMPILER_THREAD)).toList();

    /**
     * This JVM's class path less the bench's own classes: what the installed command's JVM has (the
     * demos, the simulator, the library). A sweep looks through the robot's class path for classes
     * that keep state in static fields, and this class's would count.
     */
    private static final String CLASS_PATH = withoutBenchClasses();

    /** The folders and files a 64-run sweep creates: a folder and six files per run (docs/guide.md). */
    private static final int RUN_FOLDERS = 64;
    private static final int FILES_PER_RUN = 6;

    private SweepBench() {
    }

    private static String withoutBenchClasses() {
        String bench;
        try {
            bench = Paths.get(SweepBench.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
        List<String> kept = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (!Paths.get(entry).toAbsolutePath().toString().equals(bench)) {
                kept.add(entry);
            }
        }
        return String.join(File.pathSeparator, kept);
    }

    /**
     * The folders the timed commands ran in, deleted when the bench ends: each holds a sweep's files,
     * and deleting them between the timings would slow the next one (on ext4 a file is created more
     * slowly just after many were deleted; docs/performance.md).
     */
    private static final List<Path> FOLDERS = new ArrayList<>();

    /** Runs the comparison; the working directory is the repository root. */
    public static void main(String[] args) throws Exception {
        try {
            compare();
        } finally {
            for (Path dir : FOLDERS) {
                deleteTree(dir);
            }
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> paths = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) paths.sorted(Comparator.reverseOrder())::iterator) {
                Files.delete(p);
            }
        }
    }

    private static void compare() throws Exception {
        Path properties = Paths.get("Properties/bumper.ini").toAbsolutePath();
        System.out.printf(Locale.ROOT, "RP1 sweep benchmark, %s, %d processors, Java %s, load average %.1f%n",
                LocalDate.now(), Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"),
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        String p = properties.toString();
        Path temporary = Paths.get(System.getProperty("java.io.tmpdir"));
        Path ram = ramDisk();
        System.out.printf(Locale.ROOT, "creating a %d-run sweep's %d folders and %d files: %.1f ms in %s%s%n",
                RUN_FOLDERS, RUN_FOLDERS, RUN_FOLDERS * FILES_PER_RUN, fileCreationMillis(temporary), temporary,
                ram == null ? " (no RAM disk here)" : String.format(Locale.ROOT, ", %.1f ms on the RAM disk %s",
                        fileCreationMillis(ram), ram));
        // The one run and the sweep alternate, pair by pair, each pair in the other order: a machine
        // that grows busier or quieter meanwhile moves both, and the ratio is taken within each pair.
        // The sweep on the RAM disk goes at the pair's other end: the sweep in the temporary folder stays
        // next to the one run, as before, and the two sweeps are timed next to each other.
        double[] ones = new double[PAIRS];
        double[] sweeps = new double[PAIRS];
        double[] ratios = new double[PAIRS];
        double[] ramSweeps = new double[PAIRS];
        double[] ramRatios = new double[PAIRS];
        String[] sweep = {"-p", p, "--seeds", "1-" + RUN_FOLDERS, "--jobs", "2", "--out", "OUT"};
        for (int i = 0; i < PAIRS; i++) {
            if (i % 2 == 0) {
                ones[i] = time(temporary, SIMULATOR, "rp1.Server", "-p", p);
            } else if (ram != null) {
                ramSweeps[i] = time(ram, QUICK, "rp1.Sweep", sweep);
            }
            sweeps[i] = time(temporary, QUICK, "rp1.Sweep", sweep);
            if (i % 2 == 1) {
                ones[i] = time(temporary, SIMULATOR, "rp1.Server", "-p", p);
            } else if (ram != null) {
                ramSweeps[i] = time(ram, QUICK, "rp1.Sweep", sweep);
            }
            ratios[i] = sweeps[i] / ones[i];
            if (ram != null) {
                ramRatios[i] = ramSweeps[i] / ones[i];
            }
        }
        double one = median(ones);
        double loader = median(sweeps);
        double fullJit = median(temporary, BOTH_COMPILERS, "rp1.Sweep", sweep);
        double process = median(temporary, QUICK, "rp1.Sweep", "-p", p, "--seeds", "1-8", "--jobs", "2", "--isolation",
                "process", "--out", "OUT");
        System.out.printf(Locale.ROOT, "one bumper run of 60 simulated s as a process of its own (java %s rp1.Server):"
                + " %.2f s%n", String.join(" ", SIMULATOR), one);
        double[] sorted = ratios.clone();
        Arrays.sort(sorted);
        // The target (at most 2) is the simulator's figure: the RAM disk's where there is one, since a
        // disk's recent deletions can slow the sweep's 448 creations and not the one run's one.
        System.out.printf(Locale.ROOT, "64 such runs, ./rp1 sweep --jobs 2 (--isolation loader, %s), their folders in %s:"
                + " %.2f s; %.2f times the one run (median of %d alternating pairs' ratios, %.2f to %.2f%s)%n",
                String.join(" ", QUICK), temporary, loader, median(ratios), PAIRS, sorted[0], sorted[PAIRS - 1],
                ram == null ? "; target: at most 2" : "");
        if (ram != null) {
            double[] ramSorted = ramRatios.clone();
            Arrays.sort(ramSorted);
            System.out.printf(Locale.ROOT, "the same sweep, its folders on the RAM disk %s: %.2f s; %.2f times the one run"
                    + " (the same pairs, %.2f to %.2f; the simulator's figure, without the disk's: target at most 2)%n", ram,
                    median(ramSweeps), median(ramRatios), ramSorted[0], ramSorted[PAIRS - 1]);
        }
        System.out.printf(Locale.ROOT, "the same with both compilers (without %s): %.2f s, %.1f times%n", JavaCommand.QUICK_COMPILER,
                fullJit, fullJit / one);
        System.out.printf(Locale.ROOT, "8 such runs, --isolation process: %.2f s (%.2f s a run)%n", process, process / 8);
    }

    /**
     * The median wall seconds of {@link #TRIES} runs of {@code java JVM MAIN ARGS}, each in a fresh folder
     * in {@code parent} (OUT in it).
     */
    private static double median(Path parent, List<String> jvm, String main, String... args)
            throws IOException, InterruptedException {
        double[] times = new double[TRIES];
        for (int i = 0; i < TRIES; i++) {
            times[i] = time(parent, jvm, main, args);
        }
        return median(times);
    }

    /** The RAM disk, if this machine has one this process may write in; else null. */
    private static Path ramDisk() {
        Path shm = Paths.get("/dev/shm");
        return Files.isDirectory(shm) && Files.isWritable(shm) ? shm : null;
    }

    /**
     * The milliseconds it takes to create, in a fresh folder in {@code parent}, as many folders and
     * (empty) files as a 64-run sweep creates for its runs; the folder is deleted when the bench ends,
     * as the sweeps' are, since deleting files is what makes creating them slow on some file systems.
     */
    private static double fileCreationMillis(Path parent) throws IOException {
        Path dir = keptFolder(parent);
        long start = System.nanoTime();
        for (int r = 0; r < RUN_FOLDERS; r++) {
            Path run = Files.createDirectory(dir.resolve(Integer.toString(r)));
            for (int f = 0; f < FILES_PER_RUN; f++) {
                Files.createFile(run.resolve(f + ".txt"));
            }
        }
        return (System.nanoTime() - start) * 1e-6;
    }

    /** A fresh folder in {@code parent}, kept until the bench ends (see {@link #FOLDERS}). */
    private static Path keptFolder(Path parent) throws IOException {
        Path dir = Files.createTempDirectory(parent, "rp1-sweep-bench");
        FOLDERS.add(dir);
        return dir;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }

    /** The wall seconds of one run of {@code java JVM MAIN ARGS} in a fresh folder in {@code parent} (OUT in it). */
    private static double time(Path parent, List<String> jvm, String main, String... args)
            throws IOException, InterruptedException {
        Path dir = keptFolder(parent);
        List<String> words = new ArrayList<>();
        for (String a : args) {
            words.add(a.equals("OUT") ? dir.resolve("out").toString() : a);
        }
        long start = System.nanoTime();
        Process p = new ProcessBuilder(JavaCommand.withClassPath(jvm, CLASS_PATH, main, words.toArray(new String[0])))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve("output.txt").toFile())
                .start();
        int status = p.waitFor();
        double seconds = (System.nanoTime() - start) * 1e-9;
        if (status != 0) {
            FOLDERS.remove(dir);
            throw new IllegalStateException(main + " ended with status " + status + "; see " + dir.resolve("output.txt"));
        }
        return seconds;
    }
}
