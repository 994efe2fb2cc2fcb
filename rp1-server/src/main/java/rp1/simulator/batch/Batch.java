package rp1.simulator.batch;

import java.io.Closeable;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import rp1.io.IoFailures;
import rp1.planparser.ParsedPlans;
import rp1.planparser.RsParsingException;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRunContext;
import rp1.rossum.RsSegment;
import rp1.rossum.RsWall;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ResourceLocator;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.launch.ClientClassPath;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.StartupException;
import rp1.simulator.outcome.Trail;

/**
 * Runs a server's properties over every configuration of the varied keys ({@code --vary}), seed and
 * floor plan, each run a headless world of its own ({@link SweepRun}), N at a time, and gathers what
 * they leave into {@code results.csv}. A run is a function of its properties, plan and seed and
 * nothing else: it gets them in its own {@code run.ini} and shares no state with the others, whether
 * it runs in this process with a class loader of its own ({@link LoaderRuns}) or in a process of its
 * own ({@link ProcessRuns}), so the same runs could be spread over several machines. A run that fails
 * is a row with its reason; the others go on.
 *
 * <p>A run's rows are in {@code results.csv} as soon as it ends. {@link #stop()} (the sweep was
 * interrupted) asks the runs still going to stop as Ctrl-C would, so their recordings are closed,
 * starts no others, and leaves {@code results.csv} with every run that finished; {@code --resume}
 * then runs only the others, if the folder's {@code sweep.ini} says it holds the same sweep.
 */
public final class Batch {
    /** The results in the output folder. */
    private static final String RESULTS = "results.csv";
    /**
     * The longest the first run goes alone, milliseconds of wall time: long enough for a bumper run
     * (0.2 s) to warm the process up for the others, short enough that a run of minutes, or one that
     * hangs until --timeout, does not hold every other job back for as long.
     */
    private static final long FIRST_RUN_ALONE_MILLIS = 1_000;
    /**
     * How long past a run's --timeout the sweep waits for a run to start or end before it takes its
     * process for stuck, seconds: a run timed out is stopped as Ctrl-C would stop it, which takes a
     * few seconds at most (the grace of its threads, a process killed).
     */
    static final double STUCK_AFTER_TIMEOUT_SECONDS = 60;

    private final SweepOptions options;
    private final Path out;
    /** Writes each run's folder. */
    private final RunFolder folders;
    private final Map<String, RsPlan> plans;
    private final List<Run> runs;
    private final SweepSpec spec;
    /** The runs finished by an earlier sweep into the same folder (--resume). */
    private final List<Outcome> kept;
    /** The robot's class path (-cp), made absolute. */
    private final List<Path> classPath;
    /** The engine --isolation asks for, or the one {@link #useEngine} gives. */
    private volatile RunEngine engine;
    private volatile boolean stopping;
    /** Set when a run found the output folder without its {@code sweep.ini}: removed or replaced meanwhile. */
    private volatile boolean outputLost;
    /** When a run last started or ended, {@link System#nanoTime()}: a sweep with runs left and none for long is stuck. */
    private volatile long lastProgress;
    /** How long without a run starting or ending makes the sweep stuck, nanoseconds. */
    private long stuckNanos;

    /**
     * One run of the sweep and the folder it runs in.
     *
     * @param configuration the value of each varied key, in the order of {@code --vary}
     */
    public record Run(Map<String, String> configuration, long seed, String plan, Path dir) {
        /** Copies the map. */
        public Run {
            configuration = Collections.unmodifiableMap(new LinkedHashMap<>(configuration));
        }
    }

    /** How a run went, and the trails its robots left. */
    public record Outcome(Run run, RunReport report, double wallSeconds, List<Trail> trails) {
    }

    /**
     * How the sweep went: the outcome of every finished run (now or, with --resume, before), in the
     * order of {@link #runs()}, and whether it was stopped before every run had finished.
     */
    public record Result(List<Outcome> outcomes, boolean interrupted) {
    }

    private Batch(SweepOptions options, Path out, String propertiesText, Map<String, RsPlan> plans, List<Run> runs,
                  SweepSpec spec, List<Outcome> kept, List<Path> classPath, RunEngine engine) {
        this.options = options;
        this.out = out;
        this.folders = new RunFolder(propertiesText, options.client, options.pictures);
        this.plans = plans;
        this.runs = runs;
        this.spec = spec;
        this.kept = kept;
        this.classPath = List.copyOf(classPath);
        this.engine = engine;
    }

    /**
     * Loads what {@link #prepare} uses of the JDK for the first time in a JVM and not on its own
     * account (the security providers behind sweep.ini's digest: 10 ms of class loading), for a caller
     * to do on another thread while it parses its options, rather than on the way to the first run.
     */
    public static void warmUp() {
        SweepSpec.warmUp();
    }

    /**
     * Checks everything that can be checked before a run starts: the properties of every
     * configuration (valid, loading a client or given one with {@code --client}, bounding every run),
     * the plans (found and parsed), the output folder, and with {@code --resume} that the folder holds
     * the same sweep (whose finished runs are then kept).
     *
     * @param workingDirectory where the properties and plans are looked for first, as the server does
     * @param loader           where the robots' classes are found
     * @throws SweepException saying what is wrong
     */
    public static Batch prepare(SweepOptions options, Path workingDirectory, ClassLoader loader) throws SweepException {
        ResourceLocator locator = new ResourceLocator(workingDirectory, loader);
        try {
            List<Path> classPath = ClientClassPath.resolve(options.classPath, workingDirectory);
            ResourceLocator.Found found = locator.properties(options.properties);
            Properties table = ResourceLocator.parseProperties(found);
            String firstPlan = options.plans.isEmpty() ? null : options.plans.get(0);
            List<Map<String, String>> configurations = Varied.product(options.varied);
            Set<String> robotClasses = new LinkedHashSet<>();
            String planName = null;
            for (Map<String, String> c : configurations) {
                ServerConfig config = configuration(table, c, options.client, found.location, firstPlan);
                checkRunnable(config, found.location + describe(c), options.client != null);
                robotClasses.addAll(config.dlcNames);
                planName = config.floorPlanFileName;
            }
            List<String> names = options.plans.isEmpty() ? List.of(planName) : options.plans;
            Map<String, RsPlan> plans = new LinkedHashMap<>();
            Map<String, String> planTexts = new LinkedHashMap<>();
            // Parsed here once for the whole sweep: the runs in this process get copies of these.
            ParsedPlans parsed = new ParsedPlans();
            for (String name : names) {
                ResourceLocator.Found text = locator.plan(name);
                RsPlan plan = plan(parsed, text);
                planTexts.put(name, text.text + imagedWalls(name, text.text, plan));
                plans.put(name, plan);
            }
            Path out = options.out.toAbsolutePath();
            if (out.toString().matches(".*\\s.*")) {
                throw new SweepException("--out " + out + ": the path must not contain white space (a property"
                        + " value ends at the first space, and each run's files are named in its properties)");
            }
            ClassLoader robots = ClientClassPath.loader(classPath, loader);
            if (options.client == null) {
                // Found before the first run, not failed in every run one by one.
                for (String name : robotClasses) {
                    if (robots.getResource(name.replace('.', '/') + ".class") == null) {
                        throw new SweepException(found.location + ": dlcName=" + name + ": no such class on the robot's"
                                + " class path" + (classPath.isEmpty() ? " (give the robot's classes with -cp)"
                                : " (-cp " + classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)) + ")"));
                    }
                }
            }
            String robotCode;
            try {
                robotCode = RobotCode.fingerprint(classPath, robotClasses, robots, options.client, workingDirectory);
            } catch (UncheckedIOException e) {
                throw new SweepException("cannot read the robot's code: " + IoFailures.why(e.getCause()));
            }
            if (!options.resume) {
                refuseToOverwrite(out);
            }
            SweepSpec spec = SweepSpec.of(found.text, planTexts, options, robotCode);
            List<Run> runs = runs(configurations, options.seeds, plans.keySet(), out.resolve("runs"));
            List<Outcome> kept = options.resume ? kept(out, spec, runs, options) : List.of();
            if (options.isolation == SweepOptions.Isolation.PROCESS && robots != loader && robots instanceof Closeable c) {
                closeQuietly(c); // each run loads the robot in a process of its own
            }
            RunEngine engine = options.isolation == SweepOptions.Isolation.PROCESS
                    ? RunEngine.inProcesses(options.timeoutSeconds, classPath)
                    : inThisProcess(robotClasses, robots, options.timeoutSeconds, classPath, parsed);
            return new Batch(options, out, found.text, plans, runs, spec, kept, classPath, engine);
        } catch (ConfigException e) {
            throw new SweepException(e.getMessage());
        } catch (StartupException e) {
            throw new SweepException("-cp: " + e.getMessage());
        }
    }

    /**
     * The engine for --isolation loader: the runs in this process, unless a class of the robot's calls
     * System.exit, which would end them all at once: then in processes of their own, as --isolation
     * process would, with the same results. The runs after one whose robot left a thread running also
     * go to processes of their own, and so do the runs going when memory runs short and those after
     * them ({@link LoaderRuns}).
     */
    private static RunEngine inThisProcess(Collection<String> robotClasses, ClassLoader robots, double timeoutSeconds,
                                           List<Path> classPath, ParsedPlans plans) {
        LoaderRuns here = new LoaderRuns(new ArrayList<>(robotClasses), robots, timeoutSeconds, plans,
                () -> RunEngine.inProcesses(timeoutSeconds, classPath));
        Optional<String> exits = here.exitCall();
        if (exits.isEmpty()) {
            return here;
        }
        here.close();
        return new ProcessRuns(timeoutSeconds, classPath, "each run went in a process of its own: " + exits.get()
                + ", which would end every run in the sweep's process at once");
    }

    /**
     * A sweep's results are not lost to the next one: without {@code --resume} the output folder must
     * be new or empty (a sweep into one that held a sweep replaced its results.csv, and left its other
     * runs' folders beside rows that no longer named them).
     */
    private static void refuseToOverwrite(Path out) throws SweepException {
        if (!Files.isDirectory(out)) {
            return;
        }
        boolean empty;
        try (Stream<Path> entries = Files.list(out)) {
            empty = entries.findAny().isEmpty();
        } catch (IOException e) {
            throw new SweepException("--out " + out + ": " + IoFailures.why(e));
        }
        if (empty) {
            return;
        }
        if (Files.exists(out.resolve(SweepSpec.FILE))) {
            throw new SweepException("--out " + out + " holds a sweep already (" + SweepSpec.FILE + "): add --resume to"
                    + " go on with it, or give another --out (or delete that one), so that its results are not lost");
        }
        throw new SweepException("--out " + out + " is not empty and holds no sweep: give a new or empty folder");
    }

    private static void closeQuietly(Closeable c) {
        try {
            c.close();
        } catch (IOException e) {
            // Only open jars of a loader no run uses.
        }
    }

    /** The properties with a configuration's values (and a {@code --client}'s keys) over them, checked. */
    private static ServerConfig configuration(Properties table, Map<String, String> values, String client,
                                              String location, String plan) throws ConfigException {
        Properties p = new Properties();
        p.putAll(table);
        p.putAll(values);
        if (client != null) {
            p.putAll(RunFolder.CLIENT_KEYS);
        }
        try {
            return ServerConfig.from(p, location, plan);
        } catch (ConfigException e) {
            throw values.isEmpty() ? e : new ConfigException(e.getMessage() + " (with --vary" + describe(values) + ")");
        }
    }

    static String describe(Map<String, String> configuration) {
        StringBuilder b = new StringBuilder();
        configuration.forEach((k, v) -> b.append(' ').append(k).append('=').append(v));
        return b.toString();
    }

    /** A run must load its robot (or be given one with --client), and must end by itself. */
    private static void checkRunnable(ServerConfig config, String location, boolean client) throws SweepException {
        if (client) {
            // The program reads its parameters from variables named after them, letters, digits and _ only.
            Map<String, String> byVariable = new HashMap<>();
            for (String name : config.parameters.keySet()) {
                String variable = RsRunContext.parameterVariable(name);
                String other = byVariable.put(variable, name);
                if (other != null) {
                    throw new SweepException(location + ": param." + other + " and param." + name + " would both reach"
                            + " the --client program as " + variable + ": rename one");
                }
            }
            return;
        }
        if (!config.dlcEnabled) {
            throw new SweepException(location + ": no robot is loaded: set dlcEnabled=true and dlcName=CLASS (or give"
                    + " the robot's program with --client)");
        }
        if (!config.exitWhenClientsDone && Double.isInfinite(config.maxSimulationTime)) {
            throw new SweepException(location + ": neither maxSimulationTime nor exitWhenClientsDone is set, so a run"
                    + " might never end: set maxSimulationTime=SECONDS (or exitWhenClientsDone=true)");
        }
    }

    /**
     * For a plan whose walls come from a map image (a map's {@code .yaml}, or a {@code bitmap} in plan
     * text), what {@code --resume} must also find unchanged: the walls the image gave, which its text
     * does not hold (an image edited between the two halves of a sweep made one sweep of two worlds).
     * Empty for other plans, whose text is all of them.
     */
    static String imagedWalls(String name, String text, RsPlan plan) {
        if (!readsAnImage(name, text)) {
            return "";
        }
        MessageDigest digest;
        try {
            digest = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
        ByteBuffer edge = ByteBuffer.allocate(4 * Double.BYTES);
        for (RsWall w : plan.getWallArray()) {
            for (RsSegment e : w.getSegmentArray()) {
                edge.clear();
                edge.putDouble(e.x).putDouble(e.y).putDouble(e.v.x).putDouble(e.v.y);
                digest.update(edge.array());
            }
        }
        return "\0walls " + HexFormat.of().formatHex(digest.digest());
    }

    /**
     * Whether the plan named {@code name} with this text takes walls from an image file: a map's
     * {@code .yaml}, or plan text with a {@code bitmap} (the word may also stand in a comment or a
     * name, which only makes the answer yes where no image is read).
     */
    public static boolean readsAnImage(String name, String text) {
        String lower = name.toLowerCase(Locale.ROOT);
        return lower.endsWith(".yaml") || lower.endsWith(".yml") || text.contains("bitmap");
    }

    /** The sweep's own copy of the plan {@code text} holds (for its picture), parsed into {@code parsed}. */
    private static RsPlan plan(ParsedPlans parsed, ResourceLocator.Found text) throws SweepException {
        try {
            return parsed.copyOf(text.text, text.location);
        } catch (RsParsingException e) {
            throw new SweepException(e.getMessage());
        } catch (IOException e) {
            throw new SweepException(text.location + ": cannot read the plan's map: " + IoFailures.why(e));
        }
    }

    /**
     * The runs an earlier sweep into {@code out} carried out, if it was the same sweep; refused with
     * what differs if it was another. A row of a run that was not carried out (it could not be started,
     * or a cluster lost it) is dropped, and the run runs again.
     */
    private static List<Outcome> kept(Path out, SweepSpec spec, List<Run> runs, SweepOptions options)
            throws SweepException {
        List<String> differences = SweepSpec.read(out).differences(spec);
        if (!differences.isEmpty()) {
            boolean format = differences.get(0).startsWith(SweepSpec.FORMAT_NAME);
            throw new SweepException("--resume: " + out + " holds another sweep (" + SweepSpec.FILE + "): "
                    + String.join("; ", differences) + (format ? ". An earlier version of RP1 began it and this one"
                    + " cannot go on with it: give another --out" : ". Resume it with its own options, or give another --out"));
        }
        List<ResultsCsv.Kept> rows;
        try {
            rows = ResultsCsv.read(out.resolve(RESULTS), variedKeys(options));
        } catch (IOException e) {
            throw new SweepException("--resume: " + e.getMessage());
        }
        List<Outcome> kept = new ArrayList<>();
        ResultsCsv.Kept last = rows.isEmpty() ? null : rows.get(rows.size() - 1);
        for (Run run : runs) {
            for (ResultsCsv.Kept k : rows) {
                if (k.seed() == run.seed() && k.plan().equals(run.plan()) && k.configuration().equals(run.configuration())) {
                    if (k.report().carriedOut() && (k != last || allRobots(k, run))) {
                        kept.add(new Outcome(run, k.report(), k.wallSeconds(), RunFolder.trails(run)));
                    }
                    break;
                }
            }
        }
        return kept;
    }

    /**
     * Whether the rows of the run results.csv had last are of all its named robots, as its folder's
     * report counts them (if it has one). A run's rows are appended in one write, so a sweep killed
     * while writing (or a machine that went off) can cut only the last run's: in a row, which is left
     * out, or between two robots' rows. Otherwise the run is run again.
     */
    private static boolean allRobots(ResultsCsv.Kept k, Run run) {
        if (!Files.isRegularFile(run.dir().resolve(RunReport.FILE))) {
            return true; // a run that wrote no report (killed at its timeout) has no robots: one row, whole or left out
        }
        try {
            return RunReport.read(run.dir()).robots().stream().filter(r -> !r.name().isEmpty()).count()
                    == k.report().robots().size();
        } catch (IOException e) {
            return false;
        }
    }

    private static List<String> variedKeys(SweepOptions options) {
        List<String> keys = new ArrayList<>();
        options.varied.forEach(v -> keys.add(v.key()));
        return keys;
    }

    /**
     * Configuration by configuration, plan by plan, seed by seed, each in {@code runs/SEED-PLAN} (PLAN
     * being the plan's {@link #stem}), or {@code runs/cN-SEED-PLAN} for configuration N when keys vary.
     */
    private static List<Run> runs(List<Map<String, String>> configurations, List<Long> seeds, Set<String> plans,
                                  Path runsDir) throws SweepException {
        List<Run> runs = new ArrayList<>();
        Set<String> stems = new HashSet<>();
        for (String plan : plans) {
            if (!stems.add(stem(plan))) {
                throw new SweepException("two of the plans are named " + stem(plan) + "; their runs' folders would be the same");
            }
        }
        for (int c = 0; c < configurations.size(); c++) {
            String prefix = configurations.get(c).isEmpty() ? "" : "c" + (c + 1) + "-";
            for (String plan : plans) {
                for (long seed : seeds) {
                    runs.add(new Run(configurations.get(c), seed, plan, runsDir.resolve(prefix + seed + "-" + stem(plan))));
                }
            }
        }
        return runs;
    }

    /**
     * The plan's file name without its folder and its ending ({@code .txt}, or a map's {@code .yaml} or
     * {@code .yml}), in letters a folder name may hold.
     */
    static String stem(String plan) {
        String name = Paths.get(plan).getFileName().toString();
        for (String ending : new String[] {".txt", ".yaml", ".yml"}) {
            if (name.toLowerCase(Locale.ROOT).endsWith(ending)) {
                name = name.substring(0, name.length() - ending.length());
                break;
            }
        }
        return name.replaceAll("[^A-Za-z0-9._-]", "_");
    }

    /** The options the sweep was prepared with. */
    public SweepOptions options() {
        return options;
    }

    /** The robot's class path (-cp), made absolute; empty when its classes are the simulator's. */
    public List<Path> robotClassPath() {
        return classPath;
    }

    /** What the engine tells the user about how it carries out the runs, or null. */
    public String engineNote() {
        // A --client program is the robot: no classes of a robot were loaded, shared or not.
        return options.client != null ? null : engine.note();
    }

    /** Carries out the runs with {@code engine} (rp1-spark's) rather than the one --isolation chose. */
    public void useEngine(RunEngine engine) {
        this.engine = engine;
    }

    /** The folder the results go to. */
    public Path out() {
        return out;
    }

    /** The runs, in the order of the table. */
    public List<Run> runs() {
        return runs;
    }

    /** The plans, in the order given, by the name they were given. */
    public Map<String, RsPlan> plans() {
        return plans;
    }

    /** The keys varied, in the order of their columns. */
    public List<String> variedKeys() {
        return variedKeys(options);
    }

    /** The runs an earlier sweep into the same folder carried out (--resume); they are not run again. */
    public List<Outcome> kept() {
        return kept;
    }

    /**
     * Runs every run not {@link #kept()}, {@code --jobs} at a time (the first alone for up to a
     * second if the engine {@linkplain RunEngine#firstRunWarmsUp() gains by it}), adding each one's rows to
     * {@code results.csv} as it ends; at the end rewrites {@code results.csv} in the order of the
     * runs. Stops early, with every run that finished, if {@link #stop()} is called; fails, with every
     * run that finished in {@code results.csv}, if no run starts or ends for longer than a run can take
     * ({@link #STUCK_AFTER_TIMEOUT_SECONDS} past --timeout, where the engine bounds its runs so).
     */
    public Result run(Progress progress) throws IOException, InterruptedException {
        Files.createDirectories(out.resolve("runs"));
        if (!options.resume) {
            spec.write(out);
        }
        // Keyed by each run's own folder: a record's hashCode is linked on its first call, which cost
        // 10 ms before the first run could start.
        Map<Path, Outcome> finished = new ConcurrentHashMap<>();
        kept.forEach(o -> finished.put(o.run().dir(), o));
        ExecutorService pool = Executors.newFixedThreadPool(options.jobs);
        try (ResultsCsv results = ResultsCsv.start(out.resolve(RESULTS), variedKeys(), kept)) {
            CountDownLatch jobsLeft = new CountDownLatch((int) runs.stream().filter(r -> !finished.containsKey(r.dir())).count());
            CountDownLatch firstEnded = new CountDownLatch(1);
            // What a job failed with, the first: kept rather than thrown, so that learning of it, and
            // waiting for the jobs, allocates nothing while a robot may have filled the heap.
            AtomicReference<Throwable> failed = new AtomicReference<>();
            int submitted = 0;
            for (Run r : runs) {
                if (!finished.containsKey(r.dir())) {
                    if (submitted == 1 && engine.firstRunWarmsUp()) {
                        // Two cold bumper runs at once took 0.43 s each; the first alone 0.19 s.
                        firstEnded.await(FIRST_RUN_ALONE_MILLIS, TimeUnit.MILLISECONDS);
                    }
                    CountDownLatch ended = submitted++ == 0 ? firstEnded : null;
                    pool.execute(() -> {
                        try {
                            lastProgress = System.nanoTime();
                            Outcome o = stopping ? null : execute(r);
                            lastProgress = System.nanoTime();
                            if (o != null) {
                                results.add(o);
                                finished.put(r.dir(), o);
                                progress.finished(o);
                            }
                        } catch (Throwable t) {
                            failed.compareAndSet(null, t);
                        } finally {
                            if (ended != null) {
                                ended.countDown();
                            }
                            jobsLeft.countDown();
                        }
                    });
                }
            }
            lastProgress = System.nanoTime();
            awaitUnlessStuck(jobsLeft);
            if (failed.get() != null) {
                throw new IOException("a run could not be carried out: " + failed.get(), failed.get());
            }
            // Every run has ended. (If one could not be carried out, the engine is left open: it is
            // only memory and open jars until the JVM ends.)
            engine.close();
        } finally {
            pool.shutdownNow();
            progress.close();
        }
        if (outputLost) {
            throw new IOException(out + " lost its " + SweepSpec.FILE + " while the sweep ran (was the folder removed?): the"
                    + " sweep stopped, and the files of the runs before may be gone; run it again into a new folder");
        }
        List<Outcome> outcomes = new ArrayList<>();
        for (Run r : runs) {
            Outcome o = finished.get(r.dir());
            if (o != null) {
                outcomes.add(o);
            }
        }
        ResultsCsv.write(out.resolve(RESULTS), variedKeys(), outcomes);
        return new Result(outcomes, outcomes.size() < runs.size());
    }

    /**
     * Waits for the jobs to end, unless no run starts or ends for the longest a run can take (its
     * --timeout, then its stop): then the process is stuck, a job's own thread lost (a robot filled the
     * heap, and the JDK's code around the job failed for want of memory), and waiting on would wait for
     * ever. The wait allocates next to nothing, and a look that finds no memory looks again: this is the
     * thread that must still be there when the heap is full.
     */
    private void awaitUnlessStuck(CountDownLatch jobsLeft) throws InterruptedException, IOException {
        while (!endedWithin(jobsLeft, 1)) {
            if (engine.runsEndWithinTheirTimeout() && System.nanoTime() - lastProgress > stuckNanos()) {
                stop();
                throw new IOException(String.format(Locale.ROOT, "no run started or ended for %.0f s, longer than"
                        + " a run can take (--timeout %.0f s, then its stop): the sweep's process is stuck (did a"
                        + " robot fill its heap? --isolation process gives each run its own); the runs that finished"
                        + " are in %s: add --resume to the same command to carry out the others",
                        stuckNanos() / 1e9, options.timeoutSeconds, out.resolve(RESULTS)));
            }
        }
    }

    /** Whether the jobs all ended within {@code seconds}; false also if the heap had no room for the wait. */
    private static boolean endedWithin(CountDownLatch jobsLeft, long seconds) throws InterruptedException {
        try {
            return jobsLeft.await(seconds, TimeUnit.SECONDS);
        } catch (OutOfMemoryError e) {
            // Its queue's node: a job's stop is making room meanwhile.
            Thread.sleep(10);
            return jobsLeft.getCount() == 0;
        }
    }

    /** {@link #stuckNanos}: the run's --timeout and {@link #STUCK_AFTER_TIMEOUT_SECONDS}, unless a test set it. */
    private long stuckNanos() {
        return stuckNanos > 0 ? stuckNanos : (long) ((options.timeoutSeconds + STUCK_AFTER_TIMEOUT_SECONDS) * 1e9);
    }

    /** For tests: takes the sweep for stuck after {@code seconds} without a run starting or ending. */
    void stuckAfter(double seconds) {
        stuckNanos = (long) (seconds * 1e9);
    }

    /**
     * Stops the sweep (it was interrupted): starts no more runs, and stops those going as Ctrl-C
     * would, so they close their recordings (one in a process of its own still going after a grace
     * period is killed). The runs stopped are not finished: they have no rows, and --resume runs them
     * again. Any thread; returns at once.
     */
    public void stop() {
        stopping = true;
        engine.stopAll();
    }

    /**
     * One run, by the sweep's engine. A run that cannot even be started (its folder cannot be written,
     * no process) is a row with the reason too. Null if the sweep was stopped before the run finished.
     */
    private Outcome execute(Run run) throws InterruptedException {
        long start = System.nanoTime();
        if (!Files.isRegularFile(out.resolve(SweepSpec.FILE))) {
            // The folder was removed (or replaced) under the sweep: going on would write runs into a
            // new folder with no record of the runs before, as if they were the whole sweep.
            outputLost = true;
            stop();
            return null;
        }
        RunEngine.Ran ran;
        try {
            folders.prepare(run);
            ran = engine.run(run);
        } catch (IOException e) {
            ran = new RunEngine.Ran(RunReport.failed(RunReport.NOT_STARTED + e.getMessage(),
                    ExitStatus.STARTUP_FAILED), List.of());
        } catch (OutOfMemoryError e) {
            // The job's thread found the heap full where the engine could not carry the run out again
            // elsewhere (a robot filled it): a row that says so, which --resume runs again, rather than
            // a sweep that fails with the runs after it never started.
            ran = new RunEngine.Ran(RunReport.failed(RunReport.NOT_STARTED + "the sweep's process ran out of memory ("
                    + e + ")", ExitStatus.STARTUP_FAILED), List.of());
        }
        RunReport report = ran.report();
        if (stopping && (report.endReason().equals("stopped") || Double.isNaN(report.endTime()))) {
            return null;
        }
        double wall = (System.nanoTime() - start) * 1e-9;
        return new Outcome(run, report, wall, ran.trails());
    }
}
