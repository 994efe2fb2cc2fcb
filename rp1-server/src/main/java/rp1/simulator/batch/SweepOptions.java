package rp1.simulator.batch;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import rp1.simulator.config.ServerArguments;
import rp1.simulator.config.Suggestion;

/**
 * A sweep's command line: {@code -p FILE.ini --seeds 1-16 [--vary KEY=V1,V2 ...] [--plans a.txt,b.txt]
 * [--jobs N] [--timeout S] [--isolation loader|process] [--client CMD] [--pictures] [-cp PATH] --out DIR
 * [--resume]}. Immutable.
 */
public final class SweepOptions {
    /** The most runs one sweep may have. */
    static final int MAX_RUNS = 100_000;
    /** Wall seconds a run may take unless {@code --timeout} says otherwise. */
    static final double DEFAULT_TIMEOUT = 600.0;

    /** The options, one per line or more, as {@link #usage} lists them after its first lines. */
    private static final String OPTIONS = String.join("\n",
            "  -p PROPERTIES  the server's properties: a file, or Properties/NAME on the class path; they must",
            "                 load the robot (dlcEnabled, dlcName) and bound every run (maxSimulationTime or",
            "                 exitWhenClientsDone)",
            "  --seeds SEEDS  the seeds to run: 1-16, or a list such as 1,2,5-8 (0 or more)",
            "  --vary KEY=V1,V2,...  or  --vary KEY=FROM:TO:STEP",
            "                 runs every value of a properties key (param.NAME: a parameter of the robot);",
            "                 several --vary make the full product, each configuration over every seed and plan",
            "  --plans LIST   floor plans, separated by commas (default: the properties' floorPlanFileName)",
            "  --jobs N       runs at a time (default: the number of cores)",
            "  --timeout S    wall-clock seconds after which a run is stopped and counted as failed (default 600)",
            "  --isolation I  loader (default): runs share this Java process, each with its own class loader for",
            "                 the robot's classes; process: each run in a Java process of its own (for robots",
            "                 with static state shared between instances, System.exit or threads of their own)",
            "  --client CMD   runs the program CMD (split at spaces) as each run's robot instead of a loaded one:",
            "                 it connects to the port in RP1_PORT and finds RP1_SEED, RP1_PARAM_NAME, RP1_RESULTS",
            "  --pictures     also leave a picture of each run's end, end.png, in its folder (slower)",
            "  --out DIR      where results.csv, summary.png and runs/SEED-PLAN/ go (created if need be)",
            "  -cp PATH       where the robot's classes (dlcName) are, besides the simulator's own (also --classpath)",
            "  --resume       go on with the sweep in DIR that was interrupted: run only the runs it has no",
            "                 results for, or that could not be started or a cluster lost (the options that",
            "                 decide the runs, and the robot's code, must be those it was started with)");

    /**
     * What the command line may hold, for a sweep started as {@code command} ({@code rp1 sweep},
     * {@code java rp1.Sweep}): the synopsis, ending with {@code synopsis} (the options that whoever
     * starts the sweep adds, such as {@code [--html]}), the options, then {@code more} (those options'
     * lines, indented as these are), then {@code -h}.
     */
    public static String usage(String command, String synopsis, String... more) {
        String indent = " ".repeat("usage: ".length() + command.length() + 1);
        List<String> lines = new ArrayList<>(List.of(
                "usage: " + command + " -p PROPERTIES --seeds SEEDS --out DIR [--vary KEY=VALUES ...] [--plans A.txt,B.txt]",
                indent + "[--jobs N] [--timeout S] [--isolation loader|process] [--client CMD] [--pictures]",
                indent + "[--resume]" + (synopsis.isEmpty() ? "" : " " + synopsis),
                OPTIONS));
        lines.addAll(List.of(more));
        lines.add("  -h, --help     print this and exit");
        return String.join("\n", lines);
    }

    /** How the runs are kept apart. */
    public enum Isolation {
        /** In this process, each run with its own class loader for the robot's classes and its own world. */
        LOADER,
        /** Each run in a Java process of its own. */
        PROCESS
    }

    public final String properties;
    public final List<Long> seeds;
    /** The plans asked for, or empty for the properties' own. */
    public final List<String> plans;
    public final int jobs;
    public final double timeoutSeconds;
    public final Path out;
    /** Go on with the sweep in {@link #out}: run only what it has no results for. */
    public final boolean resume;
    /** The entries of {@code -cp}, as written (relative to the working directory). */
    public final List<String> classPath;
    /** The keys varied, in the order given (the first varies slowest). */
    public final List<Varied> varied;
    public final Isolation isolation;
    /** The program that is each run's robot ({@code --client}), or null for the loaded one. */
    public final String client;
    /** Each run leaves a picture of its end ({@code --pictures}). */
    public final boolean pictures;

    private SweepOptions(String properties, List<Long> seeds, List<String> plans, int jobs, double timeoutSeconds,
                         Path out, boolean resume, List<Varied> varied, Isolation isolation, String client,
                         boolean pictures, List<String> classPath) {
        this.properties = properties;
        this.seeds = Collections.unmodifiableList(seeds);
        this.plans = Collections.unmodifiableList(plans);
        this.jobs = jobs;
        this.timeoutSeconds = timeoutSeconds;
        this.out = out;
        this.resume = resume;
        this.classPath = Collections.unmodifiableList(classPath);
        this.varied = List.copyOf(varied);
        this.isolation = isolation;
        this.client = client;
        this.pictures = pictures;
    }

    /** How many configurations the varied keys make: the product of their numbers of values. */
    public long configurations() {
        long n = 1;
        for (Varied v : varied) {
            n = Math.min((long) MAX_RUNS + 1, n * v.values().size());
        }
        return n;
    }

    /**
     * Parses the command line.
     *
     * @return the options, or null if help was asked for
     * @throws IllegalArgumentException saying what is wrong
     */
    public static SweepOptions parse(String[] args) {
        String properties = null;
        List<Long> seeds = null;
        List<String> plans = new ArrayList<>();
        int jobs = Runtime.getRuntime().availableProcessors();
        double timeout = DEFAULT_TIMEOUT;
        Path out = null;
        boolean resume = false;
        List<String> classPath = new ArrayList<>();
        List<Varied> varied = new ArrayList<>();
        Isolation isolation = Isolation.LOADER;
        String client = null;
        boolean pictures = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "-h", "--help" -> {
                    return null;
                }
                case "-p" -> properties = value(args, ++i, a);
                case "--seeds" -> seeds = seeds(value(args, ++i, a));
                case "--plans" -> plans = names(value(args, ++i, a));
                case "--jobs" -> jobs = jobs(value(args, ++i, a));
                case "--timeout" -> timeout = positive(value(args, ++i, a), a, 1.0e7);
                case "--out" -> out = Paths.get(value(args, ++i, a));
                case "--resume" -> resume = true;
                case "-cp", "-classpath", "--classpath" -> classPath.addAll(ServerArguments.entries(value(args, ++i, a)));
                case "--vary" -> varied.add(vary(varied, value(args, ++i, a)));
                case "--isolation" -> isolation = isolation(value(args, ++i, a));
                case "--client" -> client = client(value(args, ++i, a));
                case "--pictures" -> pictures = true;
                default -> throw new IllegalArgumentException(a.startsWith("-")
                        ? "unknown option " + a + Suggestion.didYouMean(a, Suggestion.optionsIn(OPTIONS))
                        : "unexpected argument " + a);
            }
        }
        List<String> missing = new ArrayList<>();
        if (properties == null) {
            missing.add("-p PROPERTIES");
        }
        if (seeds == null) {
            missing.add("--seeds LIST");
        }
        if (out == null) {
            missing.add("--out DIR");
        }
        if (!missing.isEmpty()) {
            throw new IllegalArgumentException("-p, --seeds and --out are required; missing: " + String.join(", ", missing));
        }
        SweepOptions options = new SweepOptions(properties, seeds, plans, jobs, timeout, out, resume, varied, isolation,
                client, pictures, classPath);
        if (seeds.size() * (long) Math.max(1, plans.size()) * options.configurations() > MAX_RUNS) {
            throw new IllegalArgumentException("more than " + MAX_RUNS + " runs");
        }
        return options;
    }

    private static Varied vary(List<Varied> before, String spec) {
        Varied v = Varied.parse(spec);
        for (Varied b : before) {
            if (b.key().equals(v.key())) {
                throw new IllegalArgumentException("--vary " + v.key() + " is given twice");
            }
        }
        return v;
    }

    private static Isolation isolation(String v) {
        return switch (v) {
            case "loader" -> Isolation.LOADER;
            case "process" -> Isolation.PROCESS;
            default -> throw new IllegalArgumentException("--isolation needs loader or process, got " + v);
        };
    }

    private static String client(String command) {
        if (command.isBlank()) {
            throw new IllegalArgumentException("--client needs a command");
        }
        return command.trim();
    }

    private static String value(String[] args, int i, String option) {
        if (i >= args.length) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return args[i];
    }

    /** {@code 1-16}, {@code 3}, {@code 1,2,5-8}: in the order given, each seed once. */
    static List<Long> seeds(String spec) {
        Set<Long> seeds = new LinkedHashSet<>();
        for (String part : spec.split(",", -1)) {
            int dash = part.indexOf('-', 1);
            long from = seed(dash < 0 ? part : part.substring(0, dash), spec);
            long to = dash < 0 ? from : seed(part.substring(dash + 1), spec);
            if (to < from) {
                throw new IllegalArgumentException("--seeds " + spec + ": " + part + " is not a range of seeds"
                        + " (the first is above the last)");
            }
            if (to - from >= MAX_RUNS) {
                throw new IllegalArgumentException("--seeds " + spec + ": " + part + " is more than " + MAX_RUNS
                        + " seeds, the most runs a sweep makes");
            }
            // Counted without going past TO: from + 1 overflows when TO is the largest long.
            for (long n = 0; n <= to - from && seeds.size() <= MAX_RUNS; n++) {
                seeds.add(from + n);
            }
        }
        return new ArrayList<>(seeds);
    }

    private static long seed(String s, String spec) {
        long v;
        try {
            v = Long.parseLong(s.trim());
        } catch (NumberFormatException e) {
            v = -1;
        }
        if (v < 0) {
            throw new IllegalArgumentException("--seeds " + spec + ": \"" + s + "\" is not a seed (0 or more)");
        }
        return v;
    }

    private static List<String> names(String list) {
        List<String> names = new ArrayList<>();
        for (String n : list.split(",")) {
            if (!n.trim().isEmpty()) {
                names.add(n.trim());
            }
        }
        if (names.isEmpty()) {
            throw new IllegalArgumentException("--plans needs at least one floor plan");
        }
        return names;
    }

    private static int jobs(String v) {
        int n;
        try {
            n = Integer.parseInt(v);
        } catch (NumberFormatException e) {
            n = 0;
        }
        if (n < 1 || n > 1000) {
            throw new IllegalArgumentException("--jobs needs a whole number from 1 to 1000, got " + v);
        }
        return n;
    }

    private static double positive(String v, String option, double max) {
        double d;
        try {
            d = Double.parseDouble(v);
        } catch (NumberFormatException e) {
            d = Double.NaN;
        }
        if (!(d > 0.0) || d > max) {
            throw new IllegalArgumentException(option + " needs a positive number up to " + (long) max + ", got " + v);
        }
        return d;
    }
}
