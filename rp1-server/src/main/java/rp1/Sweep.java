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
import rp1.simulator.batch.Progress;
import rp1.simulator.batch.RobotResult;
import rp1.simulator.batch.SweepException;
import rp1.simulator.batch.SweepOptions;
import rp1.simulator.batch.Trail;
import rp1.view.SweepPicture;

/**
 * Runs a robot over many seeds and floor plans (docs/guide.md, "Running many"):
 * {@code java rp1.Sweep -p FILE.ini --seeds 1-16 [--plans a.txt,b.txt] [--jobs N] [--timeout S] --out DIR}.
 * Every (seed, plan) is a headless world in a process of its own; DIR gets {@code results.csv}, one
 * row per run and robot, {@code summary.png}, every run's trails over its plan, and
 * {@code runs/SEED-PLAN/} with each run's recording, event log and end picture. Exit status 0 when
 * every run ended with status 0, 2 when one did not (its row says why), 1 when the sweep could not
 * start.
 */
public final class Sweep {
    /** Exit status when some run failed. */
    public static final int RUN_FAILED = 2;

    private Sweep() {
    }

    /** Runs the sweep; the process exits with its status. Runs still going when it is stopped are stopped too. */
    public static void main(String[] args) {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> ProcessHandle.current().children()
                .forEach(ProcessHandle::destroyForcibly), "stop the runs"));
        System.exit(run(args, System.out, System.err, System.console() != null));
    }

    /**
     * Runs the sweep the command line asks for.
     *
     * @param terminal whether {@code out} is a terminal: a progress bar, else a line per run
     * @return the exit status
     */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal) {
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
            out.println("rp1.Sweep: " + batch.runs().size() + " runs (" + options.seeds.size() + " seeds on "
                    + batch.plans().size() + " plan" + (batch.plans().size() == 1 ? "" : "s") + "), " + options.jobs
                    + " at a time, into " + batch.out());
            List<Batch.Outcome> outcomes = batch.run(new Progress(batch.runs().size(), out, terminal));
            Path summary = batch.out().resolve("summary.png");
            SweepPicture.write(summary, panels(batch.plans(), outcomes, options.seeds), keys(options.seeds));
            long failed = outcomes.stream().filter(o -> !o.report().succeeded()).count();
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
