package rp1;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.FileSystemException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

import rp1.io.IoFailures;
import rp1.simulator.batch.Batch;
import rp1.simulator.batch.Interruption;
import rp1.simulator.batch.Progress;
import rp1.simulator.batch.ResultsCsv;
import rp1.simulator.batch.ResultsNotes;
import rp1.simulator.batch.RunEngine;
import rp1.simulator.batch.RunReport;
import rp1.simulator.batch.SummaryCsv;
import rp1.simulator.batch.SweepException;
import rp1.simulator.batch.SweepOptions;
import rp1.simulator.config.PropertyKeys;
import rp1.simulator.config.ServerConfig;
import rp1.view.SweepPicture;
import rp1.web.SweepIndex;

/**
 * Runs a robot over many configurations, seeds and floor plans (docs/guide.md, "Running many" and
 * "Experiments"): {@code java rp1.Sweep -p FILE.ini --seeds 1-16 [--vary KEY=V1,V2 ...] [--plans a.txt,b.txt]
 * [--jobs N] [--timeout S] [--isolation loader|process] [--client CMD] --out DIR [--resume] [--html]}. Every run is
 * a headless world of its own; DIR gets {@code results.csv}, one row per run and robot (added as each
 * run ends), {@code summary.csv}, statistics per configuration, {@code results.md}, the columns'
 * units, {@code summary.png}, box plots and trails per configuration, {@code runs/.../} with each
 * run's recording and event log (and end picture with {@code --pictures}), and {@code sweep.ini},
 * what the sweep was, for
 * {@code --resume}, and {@code index.html}, the summary and a sortable table of the runs, each linked
 * to its replay page (written with {@code --html}). Exit status 0 when every run ended with
 * status 0, 2 when one did not (its row says why), 1 when the sweep could not start, 130 when it was
 * interrupted (Ctrl-C, SIGTERM): the runs going were stopped cleanly, those finished are in the
 * results, and the message says how to go on.
 */
public final class Sweep {
    /** The option that writes every run's replay page beside its recording, linked from index.html. */
    private static final String HTML = "--html";
    /** The command that starts a sweep through this class directly, as its usage and advice name it. */
    private static final String DIRECT = "java rp1.Sweep";
    /** Exit status when some run failed. */
    public static final int RUN_FAILED = 2;

    private Sweep() {
    }

    /**
     * Runs the sweep; the process exits with its status. Ctrl-C or SIGTERM stops the runs going
     * cleanly and keeps the finished ones ({@link Interruption}).
     */
    public static void main(String[] args) {
        main(DIRECT, args);
    }

    /**
     * {@link #main(String[])} for a sweep started as {@code command} ({@code rp1 sweep}): its usage and
     * its advice on going on after an interruption name that command.
     */
    public static void main(String command, String[] args) {
        Interruption.runAndExit(command, i -> run(new Invocation(command, List.of(args)), args, System.out, System.err,
                System.console() != null, i, null));
    }

    /**
     * How the user started the sweep, as its usage and its advice on going on after an interruption
     * repeat it: the command ({@code rp1 sweep}, {@code java rp1.Sweep}) and the words given after it
     * (those of rp1-spark's sweep include {@code --master}, and not the {@code --jobs} it works out).
     */
    public record Invocation(String command, List<String> words) {
        /** Copies the words. */
        public Invocation {
            words = List.copyOf(words);
        }
    }

    /** The usage of a sweep started as {@code command}, with the options this class adds. */
    static String usage(String command) {
        return usage(command, "[--master URL]",
                "  --master URL   run on Apache Spark: local[N] or spark://HOST:PORT (rp1 cluster starts one);",
                "                 rp1 sweep --master local -h says more");
    }

    /**
     * The usage of a sweep started as {@code command} with the options this class adds and then
     * {@code more}, which {@code synopsis} sums up (rp1-spark's).
     */
    public static String usage(String command, String synopsis, String... more) {
        List<String> lines = new ArrayList<>(List.of(
                "  --html         also write each run's replay page (runs/SEED-PLAN/replay.html), linked from",
                "                 DIR/index.html"));
        lines.addAll(List.of(more));
        return SweepOptions.usage(command, "[--html] " + synopsis, lines.toArray(new String[0]));
    }

    /** {@link #run(String[], PrintStream, PrintStream, boolean, Interruption)}, never interrupted. */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal) {
        return run(args, out, err, terminal, new Interruption());
    }

    /**
     * Runs the sweep the command line asks for.
     *
     * @param terminal     whether {@code out} is a terminal: a progress bar, else a line per run
     * @param interruption stops the sweep when asked to
     * @return the exit status
     */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal, Interruption interruption) {
        return run(args, out, err, terminal, interruption, null);
    }

    /**
     * Runs the sweep the command line asks for, its runs carried out by the engine {@code engines}
     * makes (rp1-spark's), or by the one {@code --isolation} asks for if it is null.
     *
     * @return the exit status
     */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal, Interruption interruption,
                          RunEngine.Factory engines) {
        return run(new Invocation(DIRECT, List.of(args)), args, out, err, terminal, interruption, engines);
    }

    /**
     * {@link #run(String[], PrintStream, PrintStream, boolean, Interruption, RunEngine.Factory)} for a
     * sweep the user started as {@code how} says, which its usage and its advice on going on after an
     * interruption repeat.
     */
    public static int run(Invocation how, String[] args, PrintStream out, PrintStream err, boolean terminal,
                          Interruption interruption, RunEngine.Factory engines) {
        String usage = usage(how.command());
        SweepOptions options;
        boolean pages = Arrays.asList(args).contains(HTML);
        try {
            options = SweepOptions.parse(Arrays.stream(args).filter(a -> !a.equals(HTML)).toArray(String[]::new));
        } catch (IllegalArgumentException e) {
            err.println("rp1.Sweep: " + e.getMessage() + "\n" + usage);
            return 1;
        }
        if (options == null) {
            out.println(usage);
            return 0;
        }
        // What the sweep uses of the JDK for the first time is loaded on a second processor while this
        // one prepares the sweep: the digest of sweep.ini is wanted within 50 ms, the picture at the end.
        Thread warmUp = new Thread(() -> {
            Batch.warmUp();
            SweepPicture.warmUp();
        }, "rp1-warm-up");
        warmUp.setDaemon(true);
        warmUp.start();
        try {
            Batch batch = Batch.prepare(options, Paths.get("").toAbsolutePath(), Sweep.class.getClassLoader());
            if (engines != null) {
                batch.useEngine(engines.open(batch));
            }
            interruption.onStop(batch::stop);
            int toRun = batch.runs().size() - batch.kept().size();
            out.println("rp1.Sweep: " + batch.runs().size() + " runs (" + (options.varied.isEmpty() ? ""
                    : options.configurations() + " configurations, ") + options.seeds.size() + " seeds on "
                    + batch.plans().size() + " plan" + (batch.plans().size() == 1 ? "" : "s") + "), " + options.jobs
                    + " at a time, into " + batch.out()
                    + (options.resume ? "; " + batch.kept().size() + " finished before, " + toRun + " to run" : ""));
            Batch.Result result = batch.run(new Progress(toRun, out, terminal));
            List<Batch.Outcome> outcomes = result.outcomes();
            Path summary = batch.out().resolve("summary.png");
            // The picture is most of a sweep's last tenth of a second, on one processor: it is drawn on a
            // thread of its own while the tables are written here.
            FutureTask<Void> picture = new FutureTask<>(() -> {
                SweepSummary.write(summary, batch.variedKeys(), batch.plans(), outcomes);
                return null;
            });
            new Thread(picture, "rp1-summary-picture").start();
            SummaryCsv.write(batch.out().resolve("results.csv"), batch.out().resolve("summary.csv"), batch.variedKeys());
            ResultsNotes.write(batch.out(), batch.variedKeys(), ResultsCsv.resultNames(outcomes));
            index(batch.out(), pages, true, err);
            awaitPicture(picture, () -> index(batch.out(), pages, false, err));
            long failed = outcomes.stream().filter(o -> !o.report().succeeded()).count();
            if (result.interrupted()) {
                int missing = batch.runs().size() - outcomes.size();
                err.println("rp1.Sweep: interrupted; " + outcomes.size() + " of " + batch.runs().size() + " runs finished"
                        + " (" + failed + " failed), in " + batch.out().resolve("results.csv") + " and " + summary
                        + ". To run the other " + missing + ", add --resume to the same command:\n  " + how.command() + " "
                        + resumeArguments(how.words()));
                return Interruption.STATUS;
            }
            out.println("rp1.Sweep: " + (outcomes.size() - failed) + " runs ended as asked, " + failed + " failed; "
                    + batch.out().resolve("results.csv") + ", " + summary + ", " + batch.out().resolve(SweepIndex.NAME));
            for (String unread : unreadParameters(batch.variedKeys(), outcomes)) {
                String name = unread.substring(ServerConfig.PARAMETER_PREFIX.length());
                String meant = meant(name, outcomes);
                err.println("rp1.Sweep: --vary " + unread + ": no robot asked for it (RsClient.getRunParameter(\""
                        + name + "\")), so its configurations differ by its name alone; "
                        + (meant == null ? "is the name the robot's?" : "did you mean " + ServerConfig.PARAMETER_PREFIX
                        + meant + " (the robot asked for it)?"));
            }
            String note = batch.engineNote();
            if (note != null) {
                out.println("rp1.Sweep: " + note);
            }
            long notCarriedOut = outcomes.stream().filter(o -> !o.report().carriedOut()).count();
            if (notCarriedOut > 0) {
                err.println("rp1.Sweep: " + notCarriedOut + " of the failed runs " + (notCarriedOut == 1 ? "was" : "were")
                        + " never carried out (not started, or lost by the cluster; results.csv says why). To run "
                        + (notCarriedOut == 1 ? "it" : "them") + " again, add --resume to the same command:\n  " + how.command() + " "
                        + resumeArguments(how.words()));
            }
            return failed == 0 ? 0 : RUN_FAILED;
        } catch (SweepException e) {
            err.println("rp1.Sweep: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            // A file system's exception is its path alone: say what went wrong with it.
            err.println("rp1.Sweep: " + (e instanceof FileSystemException f && f.getFile() != null ? f.getFile() + ": " : "")
                    + IoFailures.why(e));
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("rp1.Sweep: interrupted");
            return 1;
        }
    }

    /**
     * The varied parameters ({@code param.NAME}) that no run's robot asked for, of the runs whose
     * reports know what their robots asked (loaded robots' runs carried out now); none if no report does.
     */
    static List<String> unreadParameters(List<String> varied, List<Batch.Outcome> outcomes) {
        List<RunReport> known = outcomes.stream().map(Batch.Outcome::report).filter(r -> r.parametersAsked() != null)
                .toList();
        List<String> unread = new ArrayList<>();
        for (String key : varied) {
            String name = ServerConfig.isParameter(key) ? key.substring(ServerConfig.PARAMETER_PREFIX.length()) : null;
            if (name != null && !known.isEmpty() && known.stream().noneMatch(r -> r.parametersAsked().contains(name))) {
                unread.add(key);
            }
        }
        return unread;
    }

    /**
     * The parameter the robots asked for whose name is nearest {@code name} (a typo's likely intent),
     * or null if none is within a few letters of it.
     */
    static String meant(String name, List<Batch.Outcome> outcomes) {
        String best = null;
        int bestDistance = Math.max(2, name.length() / 3) + 1;
        for (String asked : outcomes.stream().map(o -> o.report().parametersAsked()).filter(a -> a != null)
                .flatMap(List::stream).distinct().sorted().toList()) {
            int d = PropertyKeys.distance(name, asked);
            if (d < bestDistance) {
                best = asked;
                bestDistance = d;
            }
        }
        return best;
    }

    /** Waits for the summary picture; if it could not be written, does {@code instead} and throws why. */
    private static void awaitPicture(FutureTask<Void> picture, Runnable instead) throws IOException, InterruptedException {
        try {
            picture.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof IOException io) {
                instead.run();
                throw io;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw (RuntimeException) e.getCause();
        }
    }

    /**
     * Writes the sweep's index.html (with each run's replay page if asked, and showing summary.png if
     * {@code picture}); a failure is told, not fatal.
     */
    private static void index(Path dir, boolean pages, boolean picture, PrintStream err) {
        try {
            for (String failure : SweepIndex.write(dir, pages, picture)) {
                err.println("rp1.Sweep: no replay page for " + failure);
            }
        } catch (IOException e) {
            err.println("rp1.Sweep: cannot write " + dir.resolve(SweepIndex.NAME) + ": " + IoFailures.why(e));
        }
    }

    /** The command line given, with --resume, each argument quoted for a shell if need be. */
    private static String resumeArguments(List<String> given) {
        List<String> words = new ArrayList<>();
        for (String a : given) {
            words.add(a.matches("[A-Za-z0-9_./:,=+-]+") ? a : "'" + a.replace("'", "'\\''") + "'");
        }
        if (!words.contains("--resume")) {
            words.add("--resume");
        }
        return String.join(" ", words);
    }
}
