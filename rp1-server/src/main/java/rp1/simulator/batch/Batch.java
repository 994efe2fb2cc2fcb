package rp1.simulator.batch;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsPlan;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ResourceLocator;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.launch.ClientClassPath;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.JavaCommand;
import rp1.simulator.launch.StartupException;

/**
 * Runs a server's properties over several seeds and floor plans, each (seed, plan) a headless world
 * in a Java process of its own ({@link SweepRun}), N at a time, and gathers what they leave into
 * {@code results.csv}. A run is a function of its properties, plan and seed and nothing else: it gets
 * them in its own {@code run.ini} and shares no state with the others, so the same runs could be
 * spread over several machines. A run that fails is a row with its reason; the others go on.
 *
 * <p>A run's rows are in {@code results.csv} as soon as it ends. {@link #stop()} (the sweep was
 * interrupted) asks the runs still going to stop as Ctrl-C would, so their recordings are closed,
 * starts no others, and leaves {@code results.csv} with every run that finished; {@code --resume}
 * then runs only the others, if the folder's {@code sweep.ini} says it holds the same sweep.
 */
public final class Batch {
    /** Each run's recording, event log and end picture, in its folder (docs/guide.md names them). */
    private static final String RECORDING = "recording.txt";
    private static final String EVENTS = "events.txt";
    private static final String PICTURE = "end.png";
    /** What the run's process printed. */
    private static final String OUTPUT = "output.txt";
    /** How long a run that is asked to stop may take to close its files before it is killed. */
    private static final long STOP_GRACE_SECONDS = 10;
    /** The results in the output folder. */
    private static final String RESULTS = "results.csv";

    private final SweepOptions options;
    private final Path out;
    private final String propertiesText;
    private final Map<String, RsPlan> plans;
    private final List<Run> runs;
    private final SweepSpec spec;
    /** The runs finished by an earlier sweep into the same folder (--resume). */
    private final List<Outcome> kept;
    private final Set<Process> running = ConcurrentHashMap.newKeySet();
    private volatile boolean stopping;
    private final List<Path> classPath;
    /** Carries out the runs instead of a process per run, if set ({@link #useEngine}). */
    private volatile RunEngine engine;

    /** One (seed, plan) of the sweep and the folder it runs in. */
    public record Run(long seed, String plan, Path dir) {
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
                  SweepSpec spec, List<Outcome> kept, List<Path> classPath) {
        this.options = options;
        this.out = out;
        this.propertiesText = propertiesText;
        this.plans = plans;
        this.runs = runs;
        this.spec = spec;
        this.kept = kept;
        this.classPath = classPath;
    }

    /**
     * Checks everything that can be checked before a run starts: the properties (valid, loading a
     * client, bounding every run), the plans (found and parsed), the output folder, and with
     * {@code --resume} that the folder holds the same sweep (whose finished runs are then kept).
     *
     * @param workingDirectory where the properties and plans are looked for first, as the server does
     * @throws SweepException saying what is wrong
     */
    public static Batch prepare(SweepOptions options, Path workingDirectory, ClassLoader loader) throws SweepException {
        ResourceLocator locator = new ResourceLocator(workingDirectory, loader);
        try {
            List<Path> classPath = ClientClassPath.resolve(options.classPath, workingDirectory);
            ResourceLocator.Found found = locator.properties(options.properties);
            Properties table = ResourceLocator.parseProperties(found);
            ServerConfig config = ServerConfig.from(table, found.location,
                    options.plans.isEmpty() ? null : options.plans.get(0));
            checkRunnable(config, found.location);
            List<String> names = options.plans.isEmpty() ? List.of(config.floorPlanFileName) : options.plans;
            Map<String, RsPlan> plans = new LinkedHashMap<>();
            Map<String, String> planTexts = new LinkedHashMap<>();
            for (String name : names) {
                ResourceLocator.Found text = locator.plan(name);
                planTexts.put(name, text.text);
                plans.put(name, plan(text));
            }
            Path out = options.out.toAbsolutePath();
            if (out.toString().matches(".*\\s.*")) {
                throw new SweepException("--out " + out + ": the path must not contain white space (a property"
                        + " value ends at the first space, and each run's files are named in its properties)");
            }
            SweepSpec spec = SweepSpec.of(found.text, planTexts, options.seeds, options.timeoutSeconds);
            List<Run> runs = runs(options.seeds, plans.keySet(), out.resolve("runs"));
            List<Outcome> kept = options.resume ? kept(out, spec, runs) : List.of();
            return new Batch(options, out, found.text, plans, runs, spec, kept, classPath);
        } catch (ConfigException e) {
            throw new SweepException(e.getMessage());
        } catch (StartupException e) {
            throw new SweepException("-cp: " + e.getMessage());
        }
    }

    /** The run's folder, and the robot's class path made absolute (-cp), for {@link SweepRun}. */
    private String[] runArguments(Run run) {
        List<String> args = new ArrayList<>(List.of(run.dir().toAbsolutePath().toString()));
        if (!classPath.isEmpty()) {
            args.add("-cp");
            args.add(classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)));
        }
        return args.toArray(new String[0]);
    }

    /** A run must load its robot, and must end by itself. */
    private static void checkRunnable(ServerConfig config, String location) throws SweepException {
        if (!config.dlcEnabled) {
            throw new SweepException(location + ": no robot is loaded: set dlcEnabled=true and dlcName=CLASS (a sweep's"
                    + " runs have no network clients)");
        }
        if (!config.exitWhenClientsDone && Double.isInfinite(config.maxSimulationTime)) {
            throw new SweepException(location + ": neither maxSimulationTime nor exitWhenClientsDone is set, so a run"
                    + " might never end: set maxSimulationTime=SECONDS (or exitWhenClientsDone=true)");
        }
    }

    private static RsPlan plan(ResourceLocator.Found text) throws SweepException {
        try {
            return RsPlanParser.parse(text.text, text.location);
        } catch (RsParsingException e) {
            throw new SweepException(e.getMessage());
        }
    }

    /**
     * The runs an earlier sweep into {@code out} finished, if it was the same sweep; refused with what
     * differs if it was another.
     */
    private static List<Outcome> kept(Path out, SweepSpec spec, List<Run> runs) throws SweepException {
        List<String> differences = SweepSpec.read(out).differences(spec);
        if (!differences.isEmpty()) {
            throw new SweepException("--resume: " + out + " holds another sweep (" + SweepSpec.FILE + "): "
                    + String.join("; ", differences) + ". Resume it with its own options, or give another --out");
        }
        List<ResultsCsv.Kept> rows;
        try {
            rows = ResultsCsv.read(out.resolve(RESULTS));
        } catch (IOException e) {
            throw new SweepException("--resume: " + e.getMessage());
        }
        List<Outcome> kept = new ArrayList<>();
        for (Run run : runs) {
            for (ResultsCsv.Kept k : rows) {
                if (k.seed() == run.seed() && k.plan().equals(run.plan())) {
                    kept.add(new Outcome(run, k.report(), k.wallSeconds(), trails(run)));
                    break;
                }
            }
        }
        return kept;
    }

    /** Plan by plan, seed by seed, each in {@code runs/SEED-PLAN} (the plan's file name without .txt). */
    private static List<Run> runs(List<Long> seeds, Set<String> plans, Path runsDir) throws SweepException {
        List<Run> runs = new ArrayList<>();
        Set<String> stems = new HashSet<>();
        for (String plan : plans) {
            String stem = stem(plan);
            if (!stems.add(stem)) {
                throw new SweepException("two of the plans are named " + stem + "; their runs' folders would be the same");
            }
            for (long seed : seeds) {
                runs.add(new Run(seed, plan, runsDir.resolve(seed + "-" + stem)));
            }
        }
        return runs;
    }

    /** The plan's file name without its folder and its {@code .txt}, in letters a folder name may hold. */
    static String stem(String plan) {
        String name = Paths.get(plan).getFileName().toString();
        if (name.toLowerCase(Locale.ROOT).endsWith(".txt")) {
            name = name.substring(0, name.length() - 4);
        }
        return name.replaceAll("[^A-Za-z0-9._-]", "_");
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

    /** The robot's class path (-cp), made absolute; empty when its classes are the simulator's. */
    public List<Path> robotClassPath() {
        return classPath;
    }

    /** The options the sweep was prepared with. */
    public SweepOptions options() {
        return options;
    }

    /** Carries out the runs with {@code engine} rather than each in a process of its own. */
    public void useEngine(RunEngine engine) {
        this.engine = engine;
    }

    /** The runs an earlier sweep into the same folder finished (--resume); they are not run again. */
    public List<Outcome> kept() {
        return kept;
    }

    /**
     * Runs every run not {@link #kept()}, {@code --jobs} at a time, adding each one's rows to
     * {@code results.csv} as it ends; at the end rewrites {@code results.csv} in the order of the
     * runs. Stops early, with every run that finished, if {@link #stop()} is called.
     */
    public Result run(Progress progress) throws IOException, InterruptedException {
        Files.createDirectories(out.resolve("runs"));
        if (!options.resume) {
            spec.write(out);
        }
        Map<Run, Outcome> finished = new ConcurrentHashMap<>();
        kept.forEach(o -> finished.put(o.run(), o));
        ExecutorService pool = Executors.newFixedThreadPool(options.jobs);
        try (ResultsCsv results = ResultsCsv.start(out.resolve(RESULTS), kept)) {
            List<Future<?>> futures = new ArrayList<>();
            for (Run r : runs) {
                if (!finished.containsKey(r)) {
                    futures.add(pool.submit(() -> {
                        Outcome o = stopping ? null : execute(r);
                        if (o != null) {
                            results.add(o);
                            finished.put(r, o);
                            progress.finished(o);
                        }
                        return null;
                    }));
                }
            }
            for (Future<?> f : futures) {
                f.get();
            }
        } catch (ExecutionException e) {
            throw new IOException("a run could not be carried out: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
            progress.close();
        }
        List<Outcome> outcomes = new ArrayList<>();
        for (Run r : runs) {
            if (finished.containsKey(r)) {
                outcomes.add(finished.get(r));
            }
        }
        ResultsCsv.write(out.resolve(RESULTS), outcomes);
        return new Result(outcomes, outcomes.size() < runs.size());
    }

    /**
     * Stops the sweep (it was interrupted): starts no more runs, and stops those going as Ctrl-C
     * would (SIGTERM), so they close their recordings; a run still going after a grace period is
     * killed. The runs stopped are not finished: they have no rows, and --resume runs them again.
     * Any thread; returns at once.
     */
    public void stop() {
        stopping = true;
        RunEngine given = engine;
        if (given != null) {
            given.stopAll();
        }
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
     * One run in a process of its own, stopped if it takes longer than the timeout. A run that cannot
     * even be started (its folder cannot be written, no process) is a row with the reason too. Null
     * if the sweep was stopped before the run finished.
     */
    private Outcome execute(Run run) throws InterruptedException {
        long start = System.nanoTime();
        RunReport report;
        try {
            report = engine == null ? runProcess(run) : runByEngine(run);
        } catch (IOException e) {
            report = RunReport.failed("the run could not be started: " + e.getMessage(), ExitStatus.STARTUP_FAILED);
        }
        if (report == null) {
            return null;
        }
        double wall = (System.nanoTime() - start) * 1e-9;
        return new Outcome(run, report, wall, trails(run));
    }

    private RunReport runByEngine(Run run) throws IOException, InterruptedException {
        prepareFolder(run);
        RunReport report = engine.run(run);
        return stopping && (report.endReason().equals("stopped") || Double.isNaN(report.endTime())) ? null : report;
    }

    /** The run's folder with its properties, and nothing an earlier run left. */
    private void prepareFolder(Run run) throws IOException {
        Files.createDirectories(run.dir());
        Files.deleteIfExists(run.dir().resolve(RunReport.FILE));
        Files.deleteIfExists(run.dir().resolve(TrailFile.FILE));
        Files.write(run.dir().resolve(SweepRun.PROPERTIES), properties(run).getBytes(StandardCharsets.UTF_8));
    }

    private RunReport runProcess(Run run) throws IOException, InterruptedException {
        prepareFolder(run);
        Process p = new ProcessBuilder(JavaCommand.of(List.of(), SweepRun.class.getName(), runArguments(run)))
                .redirectErrorStream(true)
                .redirectOutput(run.dir().resolve(OUTPUT).toFile()).start();
        running.add(p);
        if (stopping) {
            p.destroy();
        }
        boolean ended;
        try {
            ended = p.waitFor((long) (options.timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            stop(p);
            throw e;
        } finally {
            running.remove(p);
        }
        if (!ended) {
            stop(p);
            return RunReport.failed(String.format(Locale.ROOT, "timeout: still running after %.0f s of wall time",
                    options.timeoutSeconds), p.exitValue());
        }
        RunReport report = report(run, p.exitValue());
        return stopping && (report.endReason().equals("stopped") || Double.isNaN(report.endTime())) ? null : report;
    }

    /**
     * Stops a run as Ctrl-C would, so that it closes its recording and event log (the rows worth
     * replaying are often these); forcibly if it has not stopped within a grace period.
     */
    private static void stop(Process p) throws InterruptedException {
        if (!p.isAlive()) {
            return;
        }
        p.destroy();
        if (!p.waitFor(STOP_GRACE_SECONDS, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            p.waitFor();
        }
    }

    private static RunReport report(Run run, int status) {
        try {
            return RunReport.read(run.dir());
        } catch (IOException e) {
            return RunReport.failed("the run ended with status " + status + " and no results: " + lastLine(run), status);
        }
    }

    private static List<Trail> trails(Run run) {
        try {
            return TrailFile.read(run.dir());
        } catch (IOException e) {
            return List.of();
        }
    }

    /** The last thing the run's process printed. */
    private static String lastLine(Run run) {
        try {
            List<String> lines = Files.readAllLines(run.dir().resolve(OUTPUT), StandardCharsets.UTF_8);
            for (int i = lines.size() - 1; i >= 0; i--) {
                if (!lines.get(i).isBlank()) {
                    return lines.get(i).trim();
                }
            }
            return "it printed nothing";
        } catch (IOException e) {
            return "no output (" + e.getMessage() + ")";
        }
    }

    /**
     * The user's properties with the run's own keys after them (later keys win): its seed and plan,
     * no window, and its log, recording, event log and picture in its folder.
     */
    private String properties(Run run) {
        Path d = run.dir().toAbsolutePath();
        return propertiesText + "\n\n# rp1.Sweep: seed " + run.seed() + " on " + run.plan() + "\n"
                + "randomSeed=" + run.seed() + "\n"
                + "floorPlanFileName=" + run.plan() + "\n"
                + "enableGUI=false\n"
                + "logToFile=true\n"
                + "logFileName=" + d.resolve(SweepRun.LOG) + "\n"
                + "logToSystemOut=false\n"
                + "recordFileName=" + d.resolve(RECORDING) + "\n"
                + "eventLogFileName=" + d.resolve(EVENTS) + "\n"
                + "snapshotFileName=" + d.resolve(PICTURE) + "\n"
                + "snapshotInterval=0\n";
    }
}
