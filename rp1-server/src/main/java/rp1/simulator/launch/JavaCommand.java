package rp1.simulator.launch;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** The command line that runs a class in a new JVM like this one: this Java, this class path, headless. */
public final class JavaCommand {
    /**
     * The options of a JVM that runs one simulation (the installed {@code bin/rp1}, a sweep's run in a
     * process of its own), unless {@code JAVA_OPTS} or {@code RP1_OPTS} picks a collector: the serial
     * collector. The simulation runs on one thread and keeps a small heap (tens of megabytes for a
     * thousand robots), which a stop-the-world collection of the young generation clears in
     * milliseconds; G1's concurrent machinery (its write barriers, its refinement) cost the simulation
     * thread 15–20 % with a thousand robots and more, and it kept 60 % more memory resident
     * (docs/performance.md). These are given on every machine; {@link #simulatorOptions()} adds what
     * depends on the machine.
     */
    public static final List<String> SIMULATOR_OPTIONS = List.of("-XX:+UseSerialGC");

    /**
     * Transparent huge pages for the heap, which a JVM that runs one simulation asks for where the
     * kernel gives them only to those who ask ({@link #hugePagesOnRequest}): a crowd's simulation
     * reads its robots' data all over a heap of hundreds of megabytes, and with the heap in 2 MB pages
     * instead of 4 kB ones the processor finds far more of it without walking the page tables. 10,000
     * robots ran 1.18 times as fast (median of 18 alternating pairs), 1,000 robots 1.04 times, and one
     * bumper run in as much time as without (24 pairs) with 15 MB more resident
     * (docs/performance.md). Where the kernel hands huge pages to every large region, the JVM gets them
     * without asking; where it never does, asking would only print a warning.
     */
    public static final String HUGE_PAGES = "-XX:+UseTransparentHugePages";
    /** The kernel's setting for transparent huge pages, one word of which is chosen: {@code always [madvise] never}. */
    static final Path HUGE_PAGES_SETTING = Paths.get("/sys/kernel/mm/transparent_hugepage/enabled");

    /** The quick compiler (C1) only, for JVMs whose code runs for milliseconds. */
    public static final String QUICK_COMPILER = "-XX:TieredStopAtLevel=1";

    /**
     * The quick compiler at half its usual thresholds: code that each of a sweep's runs runs a few
     * times (its start, its records) reaches the compiler after half as many runs. 64 bumper runs with
     * {@code --jobs 2} took 0.961, 0.966 and 0.975 of the wall time in three sets of 16 alternating
     * pairs (the processor time the same).
     */
    public static final String EARLY_COMPILES = "-XX:CompileThresholdScaling=0.5";

    /**
     * A young generation of 64 MB for a sweep's JVM, where runs one after another allocate gigabytes
     * of objects that die young. Left to itself the parallel collector grew it after every collection
     * (95 MB, 190, 380, 760, 1,500 MB over 1,000 bumper runs), so nearly every object went into memory
     * the process had never touched: the kernel's page faults and zeroing were 8 % of the simulation
     * thread's samples. At 64 MB it is touched once and used again: 1,000-run sweeps 0.886 of the wall
     * time with 127 MB resident instead of 718 MB, 64 runs 0.964, 32 runs of 20 robots each 0.976 with
     * 260 MB instead of 2 GB (docs/performance.md). {@code bin/rp1} leaves it out when the user's
     * options size the heap.
     */
    public static final String YOUNG_GENERATION = "-Xmn64m";

    /**
     * The options of {@code rp1 sweep}'s JVM, which runs {@code --jobs} simulations at once: the
     * parallel collector (the serial one's cheap barriers, with the young generation collected by as
     * many threads as the jobs that filled it), the quick compiler only (a run computes for
     * milliseconds, and the optimizing compiler's work for it never pays back), {@link #EARLY_COMPILES}
     * and {@link #YOUNG_GENERATION}.
     */
    public static final List<String> SWEEP_OPTIONS = List.of("-XX:+UseParallelGC", JavaCommand.QUICK_COMPILER,
            EARLY_COMPILES, YOUNG_GENERATION);

    /**
     * A sweep's JVM on a machine of {@link #FEW_PROCESSORS} processors or fewer also gets one compiler
     * thread instead of the JVM's two: while the runs warm up, a second one took a processor from the
     * jobs, and 64 bumper runs with {@code --jobs 2} on two processors took 6 % less time with one
     * (320 runs: 4 %). On larger machines the JVM's own count stands. It needs the quick compiler
     * only: with both, the JVM refuses to start with fewer than two threads, so {@code bin/rp1} leaves
     * it out when the user's options name a compiler setting.
     */
    public static final String ONE_COMPILER_THREAD = "-XX:CICompilerCount=1";
    /** See {@link #ONE_COMPILER_THREAD}. */
    public static final int FEW_PROCESSORS = 2;

    private JavaCommand() {
    }

    /**
     * The options of a JVM that runs one simulation on this machine: {@link #SIMULATOR_OPTIONS}, and
     * {@link #HUGE_PAGES} where the kernel gives huge pages on request.
     */
    public static List<String> simulatorOptions() {
        List<String> options = new ArrayList<>(SIMULATOR_OPTIONS);
        if (hugePagesOnRequest(hugePagesSetting())) {
            options.add(HUGE_PAGES);
        }
        return List.copyOf(options);
    }

    /**
     * Whether the kernel's transparent huge pages setting ({@link #HUGE_PAGES_SETTING}'s text) gives
     * huge pages to a program that asks for them and only then: {@code madvise} chosen.
     */
    static boolean hugePagesOnRequest(String setting) {
        return setting.contains("[madvise]");
    }

    private static String hugePagesSetting() {
        try {
            return Files.readString(HUGE_PAGES_SETTING);
        } catch (IOException | RuntimeException e) {
            // Not Linux, or a kernel without them.
            return "";
        }
    }

    /** The options {@code bin/rp1} gives a sweep's JVM on a machine of {@code processors} processors. */
    public static List<String> sweepOptions(int processors) {
        List<String> options = new ArrayList<>(SWEEP_OPTIONS);
        if (processors <= FEW_PROCESSORS) {
            options.add(ONE_COMPILER_THREAD);
        }
        return options;
    }

    /**
     * {@code java [jvmOptions] -Djava.awt.headless=true -cp CLASSPATH mainClass [args]}, with this
     * process's Java and class path.
     */
    public static List<String> of(List<String> jvmOptions, String mainClass, String... args) {
        return withClassPath(jvmOptions, System.getProperty("java.class.path"), mainClass, args);
    }

    /** {@code java [jvmOptions] -Djava.awt.headless=true -cp classPath mainClass [args]}, with this process's Java. */
    public static List<String> withClassPath(List<String> jvmOptions, String classPath, String mainClass,
                                             String... args) {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        command.addAll(List.of("-Djava.awt.headless=true", "-cp", classPath, mainClass));
        command.addAll(Arrays.asList(args));
        return command;
    }
}
