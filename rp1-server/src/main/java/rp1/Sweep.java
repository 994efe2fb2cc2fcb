package rp1;

import java.awt.Color;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import rp1.rossum.RsPlan;
import rp1.simulator.batch.Batch;
import rp1.simulator.batch.Interruption;
import rp1.simulator.batch.Progress;
import rp1.simulator.batch.RobotResult;
import rp1.simulator.batch.RunEngine;
import rp1.simulator.batch.SweepException;
import rp1.simulator.batch.SweepOptions;
import rp1.simulator.batch.Trail;
import rp1.view.SweepPicture;

/**
 * Runs a robot over many seeds and floor plans (docs/guide.md, "Running many"):
 * {@code java rp1.Sweep -p FILE.ini --seeds 1-16 [--plans a.txt,b.txt] [--jobs N] [--timeout S] --out DIR
 * [--resume]}. Every (seed, plan) is a headless world in a process of its own; DIR gets {@code results.csv},
 * one row per run and robot (added as each run ends), {@code summary.png}, every run's trails over
 * its plan, {@code runs/SEED-PLAN/} with each run's recording, event log and end picture, and
 * {@code sweep.ini}, what the sweep was, for {@code --resume}. Exit status 0 when every run ended with
 * status 0, 2 when one did not (its row says why), 1 when the sweep could not start, 130 when it was
 * interrupted (Ctrl-C, SIGTERM): the runs going were stopped cleanly, those finished are in the
 * results, and the message says how to go on.
 */
public final class Sweep {
    /** Exit status when some run failed. */
    public static final int RUN_FAILED = 2;

    private Sweep() {
    }

    /**
     * Runs the sweep; the process exits with its status. Ctrl-C or SIGTERM stops the runs going
     * cleanly and keeps the finished ones ({@link Interruption}).
     */
    public static void main(String[] args) {
        Interruption interruption = new Interruption();
        Runtime.getRuntime().addShutdownHook(new Thread(interruption::signalled, "stop the runs"));
        int status = 1;
        try {
            status = run(args, System.out, System.err, System.console() != null, interruption);
        } catch (RuntimeException e) {
            // A defect, not a signal: leave at once rather than let the hook wait for a sweep that is gone.
            System.err.println("rp1.Sweep: internal error: " + e);
        } finally {
            interruption.exit(status);
        }
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
     * makes (rp1-spark's), or each in a process of its own if it is null.
     *
     * @return the exit status
     */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal, Interruption interruption,
                          RunEngine.Factory engines) {
        SweepOptions options;
        try {
            options = SweepOptions.parse(args);
        } catch (IllegalArgumentException e) {
            err.println("rp1.Sweep: " + e.getMessage() + "\n" + SweepOptions.USAGE);
            return 1;
        }
        if (options == null) {
            out.println(SweepOptions.USAGE);
            return 0;
        }
        try {
            Batch batch = Batch.prepare(options, Paths.get("").toAbsolutePath(), Sweep.class.getClassLoader());
            if (engines != null) {
                batch.useEngine(engines.open(batch));
            }
            interruption.onStop(batch::stop);
            int toRun = batch.runs().size() - batch.kept().size();
            out.println("rp1.Sweep: " + batch.runs().size() + " runs (" + options.seeds.size() + " seeds on "
                    + batch.plans().size() + " plan" + (batch.plans().size() == 1 ? "" : "s") + "), " + options.jobs
                    + " at a time, into " + batch.out()
                    + (options.resume ? "; " + batch.kept().size() + " finished before, " + toRun + " to run" : ""));
            Batch.Result result = batch.run(new Progress(toRun, out, terminal));
            List<Batch.Outcome> outcomes = result.outcomes();
            Path summary = batch.out().resolve("summary.png");
            SweepPicture.write(summary, panels(batch.plans(), outcomes, options.seeds), keys(options.seeds));
            long failed = outcomes.stream().filter(o -> !o.report().succeeded()).count();
            if (result.interrupted()) {
                int missing = batch.runs().size() - outcomes.size();
                err.println("rp1.Sweep: interrupted; " + outcomes.size() + " of " + batch.runs().size() + " runs finished"
                        + " (" + failed + " failed), in " + batch.out().resolve("results.csv") + " and " + summary
                        + ". To run the other " + missing + ", add --resume to the same command:\n  rp1.Sweep "
                        + resumeArguments(args));
                return Interruption.STATUS;
            }
            out.println("rp1.Sweep: " + (outcomes.size() - failed) + " runs ended as asked, " + failed + " failed; "
                    + batch.out().resolve("results.csv") + ", " + summary);
            return failed == 0 ? 0 : RUN_FAILED;
        } catch (SweepException | IOException e) {
            err.println("rp1.Sweep: " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("rp1.Sweep: interrupted");
            return 1;
        }
    }

    /** The command line given, with --resume, each argument quoted for a shell if need be. */
    private static String resumeArguments(String[] args) {
        List<String> words = new ArrayList<>();
        for (String a : args) {
            words.add(a.matches("[A-Za-z0-9_./:,=+-]+") ? a : "'" + a.replace("'", "'\\''") + "'");
        }
        if (!words.contains("--resume")) {
            words.add("--resume");
        }
        return String.join(" ", words);
    }

    /** One panel per plan, with the trails of its runs in the colour of their seed. */
    private static List<SweepPicture.Panel> panels(Map<String, RsPlan> plans, List<Batch.Outcome> outcomes,
                                                   List<Long> seeds) {
        Map<Long, Integer> seedIndex = new HashMap<>();
        for (int i = 0; i < seeds.size(); i++) {
            seedIndex.putIfAbsent(seeds.get(i), i);
        }
        Map<String, List<SweepPicture.RunTrails>> runsByPlan = new HashMap<>();
        for (Batch.Outcome o : outcomes) {
            runsByPlan.computeIfAbsent(o.run().plan(), k -> new ArrayList<>())
                    .add(trails(o, SweepPicture.colour(seedIndex.get(o.run().seed()))));
        }
        List<SweepPicture.Panel> panels = new ArrayList<>();
        for (Map.Entry<String, RsPlan> plan : plans.entrySet()) {
            panels.add(new SweepPicture.Panel(plan.getValue(), runsByPlan.getOrDefault(plan.getKey(), List.of())));
        }
        return panels;
    }

    private static SweepPicture.RunTrails trails(Batch.Outcome o, Color colour) {
        List<double[]> pieces = new ArrayList<>();
        for (Trail t : o.trails()) {
            pieces.addAll(t.pieces());
        }
        List<double[]> ends = new ArrayList<>();
        for (RobotResult r : o.report().robots()) {
            ends.add(new double[] {r.x(), r.y()});
        }
        return new SweepPicture.RunTrails(colour, pieces, ends);
    }

    private static List<SweepPicture.Key> keys(List<Long> seeds) {
        List<SweepPicture.Key> keys = new ArrayList<>();
        for (int i = 0; i < seeds.size(); i++) {
            keys.add(new SweepPicture.Key(SweepPicture.colour(i), "seed " + seeds.get(i)));
        }
        return keys;
    }
}
