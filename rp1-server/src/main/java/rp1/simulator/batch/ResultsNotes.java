package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code results.md} beside a sweep's tables: every column of {@code results.csv} with its unit and
 * meaning, and how {@code summary.csv} is made, so that the numbers can be read without the guide.
 */
public final class ResultsNotes {
    /** The file in the output folder. */
    public static final String FILE = "results.md";
    private static final Map<String, String[]> COLUMNS = columns();

    private ResultsNotes() {
    }

    private static Map<String, String[]> columns() {
        Map<String, String[]> c = new LinkedHashMap<>();
        c.put("seed", new String[] {"", "the run's randomSeed"});
        c.put("plan", new String[] {"", "the floor plan"});
        c.put("run", new String[] {"", "the run's folder (recording.txt, events.txt, run.ini, server.log; end.png with --pictures)"});
        c.put("robot", new String[] {"", "the robot's name, its body's (with #N when robots share one)"});
        c.put("start_x", new String[] {"m", "where the robot was first placed"});
        c.put("start_y", new String[] {"m", ""});
        c.put("start_heading", new String[] {"rad", ""});
        c.put("end_x", new String[] {"m", "where it was at end_time"});
        c.put("end_y", new String[] {"m", ""});
        c.put("end_heading", new String[] {"rad", ""});
        c.put("end_time", new String[] {"s", "simulated time when the run stopped"});
        c.put("distance", new String[] {"m", "how far its body origin travelled until end_time"});
        c.put("collisions", new String[] {"count", "how many of its motions ended in a collision"});
        c.put("first_collision_time", new String[] {"s", "simulated time of the first; empty if none"});
        c.put("events", new String[] {"count", "how many events its client was sent"});
        c.put("status", new String[] {"", "the server's exit status: 0 as asked, 1 could not start, 2 a client failed,"
                + " 4 an output could not be written, 70 the simulator failed, 124 timeout"});
        c.put("reason", new String[] {"", "why the run stopped: max-simulation-time, clients-done, nobody-left, or"
                + " what went wrong"});
        c.put("wall_seconds", new String[] {"s (wall clock)", "how long the run took"});
        return c;
    }

    /** Writes the notes for a sweep varying {@code varied} whose robots reported {@code results}. */
    public static void write(Path dir, List<String> varied, Collection<String> results) throws IOException {
        StringBuilder b = new StringBuilder("# What the columns mean\n\n");
        b.append("Numbers are rounded to what the model resolves: metres, radians and simulated seconds to 4"
                + " places (0.1 mm, 0.1 mrad, 0.1 ms), wall seconds to 3, the statistics to 6 (or to 6"
                + " significant digits if that is more); the robots' own results are as reported; trailing"
                + " zeros are dropped. An empty field is \"none\".\n\n");
        b.append("## results.csv: a row per run and robot\n\n| Column | Unit | Meaning |\n|---|---|---|\n");
        varied.forEach(k -> row(b, k, "as given", "the value of " + k + " in this run (--vary)"));
        for (String c : ResultsCsv.RUN_COLUMNS) {
            row(b, c, COLUMNS.get(c)[0], COLUMNS.get(c)[1]);
        }
        results.forEach(n -> row(b, ResultsCsv.RESULT_PREFIX + n, "the robot's", "the last value the robot reported"
                + " with reportRunResult(\"" + n + "\", ...); empty if it reported none"));
        for (String c : ResultsCsv.END_COLUMNS) {
            row(b, c, COLUMNS.get(c)[0], COLUMNS.get(c)[1]);
        }
        b.append("\n## summary.csv: a row per configuration\n\n")
                .append("A configuration is a combination of the varied keys' values, a plan and a robot. `runs` is")
                .append(" how many rows it has, `failed` how many of them have a status other than 0. Each numeric")
                .append(" column M of results.csv but the headings gets, over the rows of status 0, `M_n` (how")
                .append(" many of them have a value: the mean of first_collision_time is that of the runs that")
                .append(" collided), `M_mean`, `M_sd` (sample standard deviation), `M_ci95` (the mean's 95 %")
                .append(" confidence interval is M_mean ± M_ci95, by Student's t with M_n - 1 degrees of")
                .append(" freedom), `M_min` and `M_max`, in M's unit. The headings are angles, whose plain mean")
                .append(" means nothing, and are left out.\n");
        Files.write(dir.resolve(FILE), b.toString().getBytes(StandardCharsets.UTF_8));
    }

    private static void row(StringBuilder b, String column, String unit, String meaning) {
        b.append("| `").append(column).append("` | ").append(unit).append(" | ").append(meaning).append(" |\n");
    }
}
