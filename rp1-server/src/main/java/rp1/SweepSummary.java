package rp1;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.rossum.RsPlan;
import rp1.simulator.batch.Batch;
import rp1.simulator.batch.ResultsCsv;
import rp1.simulator.outcome.RobotResult;
import rp1.simulator.outcome.Trail;
import rp1.view.BoxPlot;
import rp1.view.SweepPicture;

/**
 * A sweep's {@code summary.png} from its results: a colour and a number per configuration of
 * {@code summary.csv} (varied values, plan, robot), a box plot of each metric worth comparing, and
 * the trails of each configuration's runs over its plan; {@link SweepPicture} draws it.
 */
final class SweepSummary {
    /** The metrics drawn as box plots, with their units, before the robots' own results. */
    private static final Map<String, String> METRICS = metrics();

    private SweepSummary() {
    }

    private static Map<String, String> metrics() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("distance", "distance (m)");
        m.put("collisions", "collisions");
        m.put("first_collision_time", "first collision (s)");
        m.put("events", "events");
        return m;
    }

    /**
     * Writes the picture.
     *
     * @param outcomes the runs, in the sweep's order: their configurations are numbered in the order
     *                 summary.csv has them (first seen), robots without a name left out
     */
    static void write(Path file, List<String> varied, Map<String, RsPlan> plans, List<Batch.Outcome> outcomes)
            throws IOException {
        List<Map<String, String>> drawn = configurations(outcomes, varied);
        List<SweepPicture.Key> keys = new ArrayList<>();
        List<SweepPicture.Panel> panels = new ArrayList<>();
        for (int i = 0; i < drawn.size(); i++) {
            Map<String, String> c = drawn.get(i);
            String label = (i + 1) + ": " + String.join(", ", describe(c, varied));
            keys.add(new SweepPicture.Key(SweepPicture.colour(i), label));
            panels.add(new SweepPicture.Panel(label, SweepPicture.colour(i), plans.get(c.get("plan")),
                    trails(outcomes, c, varied)));
        }
        List<BoxPlot.Metric> metrics = new ArrayList<>();
        // Loops rather than streams here and below: each stream's lambdas are linked on first use, and
        // this runs once, after the last run, where the sweep waits for the picture.
        Set<String> results = new LinkedHashSet<>();
        for (Batch.Outcome o : outcomes) {
            for (RobotResult r : o.report().robots()) {
                results.addAll(r.results().keySet());
            }
        }
        List<String> names = new ArrayList<>(METRICS.keySet());
        for (String n : results) {
            names.add(ResultsCsv.RESULT_PREFIX + n);
        }
        for (String name : names) {
            List<BoxPlot.Box> boxes = new ArrayList<>();
            for (int i = 0; i < drawn.size(); i++) {
                boxes.add(new BoxPlot.Box(Integer.toString(i + 1), SweepPicture.colour(i),
                        values(outcomes, drawn.get(i), varied, name)));
            }
            metrics.add(new BoxPlot.Metric(METRICS.getOrDefault(name, name), boxes));
        }
        SweepPicture.write(file, metrics, panels, keys);
    }

    /** The configurations of the runs' robots as summary.csv names them (varied keys, plan, robot), first seen first. */
    private static List<Map<String, String>> configurations(List<Batch.Outcome> outcomes, List<String> varied) {
        Set<Map<String, String>> seen = new LinkedHashSet<>();
        for (Batch.Outcome o : outcomes) {
            for (RobotResult r : o.report().robots()) {
                if (!r.name().isEmpty()) {
                    Map<String, String> c = new LinkedHashMap<>();
                    for (String k : varied) {
                        c.put(k, o.run().configuration().get(k));
                    }
                    c.put("plan", o.run().plan());
                    c.put("robot", r.name());
                    seen.add(c);
                }
            }
        }
        return new ArrayList<>(seen);
    }

    private static List<String> describe(Map<String, String> c, List<String> varied) {
        List<String> words = new ArrayList<>();
        for (String k : varied) {
            words.add(k + "=" + c.get(k));
        }
        words.add(Path.of(c.get("plan")).getFileName().toString());
        words.add(c.get("robot"));
        return words;
    }

    /** Whether the robot's row of the outcome belongs to configuration {@code c}. */
    private static boolean in(Batch.Outcome o, String robot, Map<String, String> c, List<String> varied) {
        for (String k : varied) {
            if (!c.get(k).equals(o.run().configuration().get(k))) {
                return false;
            }
        }
        return c.get("plan").equals(o.run().plan()) && c.get("robot").equals(robot);
    }

    private static List<SweepPicture.RunTrails> trails(List<Batch.Outcome> outcomes, Map<String, String> c,
                                                       List<String> varied) {
        List<SweepPicture.RunTrails> runs = new ArrayList<>();
        for (Batch.Outcome o : outcomes) {
            for (RobotResult r : o.report().robots()) {
                if (in(o, r.name(), c, varied)) {
                    List<double[]> pieces = new ArrayList<>();
                    for (Trail t : o.trails()) {
                        if (t.robot().equals(r.name())) {
                            pieces.addAll(t.pieces());
                        }
                    }
                    runs.add(new SweepPicture.RunTrails(pieces, points(r.start()), points(r.end())));
                }
            }
        }
        return runs;
    }

    private static List<double[]> points(RobotResult.Pose p) {
        return Double.isNaN(p.x()) ? List.of() : List.of(new double[] {p.x(), p.y()});
    }

    private static double[] values(List<Batch.Outcome> outcomes, Map<String, String> c, List<String> varied,
                                   String metric) {
        double[] values = new double[outcomes.size()];
        int n = 0;
        for (Batch.Outcome o : outcomes) {
            if (!o.report().succeeded()) {
                continue; // as in summary.csv: a failed run's numbers are of a run that did not go as asked
            }
            for (RobotResult r : o.report().robots()) {
                if (in(o, r.name(), c, varied)) {
                    double v = value(r, metric);
                    if (!Double.isNaN(v)) {
                        if (n == values.length) {
                            values = Arrays.copyOf(values, Math.max(1, 2 * n));
                        }
                        values[n++] = v;
                    }
                }
            }
        }
        return Arrays.copyOf(values, n);
    }

    private static double value(RobotResult r, String metric) {
        return switch (metric) {
            case "distance" -> r.distance();
            case "collisions" -> r.collisions();
            case "first_collision_time" -> r.firstCollisionTime();
            case "events" -> r.events();
            default -> r.results().getOrDefault(metric.substring(ResultsCsv.RESULT_PREFIX.length()), Double.NaN);
        };
    }
}
