package rp1.simulator.batch;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.io.WholeFiles;
import rp1.simulator.outcome.RobotResult;

/**
 * A sweep's {@code results.csv}: one row per run and robot, with a column per varied key and per
 * result the robots reported of their own ({@code result.NAME}), numbers rounded as {@link Numbers}
 * says. While the sweep goes, a run's rows are appended (and on disk) as soon as it ends, so an
 * interrupted sweep keeps what it finished; a run that reports a result no run before it did has the
 * file rewritten with the new column. At the end the file is rewritten with the runs in the order
 * they were listed.
 */
public final class ResultsCsv implements AutoCloseable {
    /** The columns between the varied keys and the robots' own results. */
    public static final List<String> RUN_COLUMNS = List.of("seed", "plan", "run", "robot", "start_x", "start_y",
            "start_heading", "end_x", "end_y", "end_heading", "end_time", "distance", "collisions",
            "first_collision_time", "events");
    /** The columns after the robots' own results. */
    public static final List<String> END_COLUMNS = List.of("status", "reason", "wall_seconds");
    /** The prefix of the columns of the robots' own results. */
    public static final String RESULT_PREFIX = "result.";

    /** A run's rows read back: the run, how it ended, and its wall-clock time. */
    record Kept(Map<String, String> configuration, long seed, String plan, RunReport report, double wallSeconds) {
    }

    private final Path file;
    private final List<String> varied;
    private final Set<String> resultNames = new LinkedHashSet<>();
    private final List<Batch.Outcome> written = new ArrayList<>();
    private OutputStream out;

    private ResultsCsv(Path file, List<String> varied) {
        this.file = file;
        this.varied = List.copyOf(varied);
    }

    /**
     * Starts {@code file} afresh with the header and the rows of {@code kept} (the runs an earlier
     * sweep finished), then keeps it open for {@link #add}.
     *
     * @param varied the varied keys, in the order of their columns
     */
    static ResultsCsv start(Path file, List<String> varied, List<Batch.Outcome> kept) throws IOException {
        ResultsCsv csv = new ResultsCsv(file, varied);
        csv.written.addAll(kept);
        csv.resultNames.addAll(resultNames(kept));
        csv.rewrite();
        return csv;
    }

    /** Appends the rows of a run that has ended (rewriting the file if it brings a new column); on disk when this returns. */
    synchronized void add(Batch.Outcome outcome) throws IOException {
        written.add(outcome);
        if (resultNames.addAll(resultNames(List.of(outcome)))) {
            rewrite();
            return;
        }
        out.write(text(rows(outcome, varied, resultNames)).getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    private void rewrite() throws IOException {
        if (out != null) {
            out.close();
        }
        write(file, varied, written);
        out = Files.newOutputStream(file, StandardOpenOption.APPEND);
    }

    @Override
    public synchronized void close() throws IOException {
        out.close();
    }

    /** Writes the rows of {@code outcomes} into {@code file}, replacing it in one step. */
    public static void write(Path file, List<String> varied, List<Batch.Outcome> outcomes) throws IOException {
        Set<String> names = resultNames(outcomes);
        List<List<String>> rows = new ArrayList<>();
        rows.add(header(varied, names));
        for (Batch.Outcome o : outcomes) {
            rows.addAll(rows(o, varied, names));
        }
        WholeFiles.writeString(file, text(rows));
    }

    /** The names of the results the robots of {@code outcomes} reported, in the order first seen. */
    public static Set<String> resultNames(Collection<Batch.Outcome> outcomes) {
        Set<String> names = new LinkedHashSet<>();
        for (Batch.Outcome o : outcomes) {
            for (RobotResult r : o.report().robots()) {
                names.addAll(r.results().keySet());
            }
        }
        return names;
    }

    /** The header: the varied keys, {@link #RUN_COLUMNS}, a column per result, {@link #END_COLUMNS}. */
    public static List<String> header(List<String> varied, Collection<String> resultNames) {
        List<String> h = new ArrayList<>(varied);
        h.addAll(RUN_COLUMNS);
        resultNames.forEach(n -> h.add(RESULT_PREFIX + n));
        h.addAll(END_COLUMNS);
        return h;
    }

    /** The rows of one run: one per robot, or one without a robot if it has none. */
    static List<List<String>> rows(Batch.Outcome o, List<String> varied, Collection<String> resultNames) {
        RunReport r = o.report();
        List<String> start = new ArrayList<>();
        varied.forEach(k -> start.add(o.run().configuration().get(k)));
        start.add(Long.toString(o.run().seed()));
        start.add(o.run().plan());
        start.add(o.run().dir().getParent().getFileName() + "/" + o.run().dir().getFileName());
        List<String> end = List.of(Integer.toString(r.exitStatus()), r.endReason(),
                Numbers.format(o.wallSeconds(), Numbers.WALL));
        String endTime = Numbers.format(r.endTime(), Numbers.MODEL);
        List<List<String>> rows = new ArrayList<>();
        if (r.robots().isEmpty()) {
            List<String> row = new ArrayList<>(start);
            for (int i = 3; i < RUN_COLUMNS.size(); i++) {
                row.add(RUN_COLUMNS.get(i).equals("end_time") ? endTime : "");
            }
            resultNames.forEach(n -> row.add(""));
            row.addAll(end);
            rows.add(row);
        }
        for (RobotResult robot : r.robots()) {
            List<String> row = new ArrayList<>(start);
            row.add(robot.name());
            pose(row, robot.start());
            pose(row, robot.end());
            row.add(endTime);
            row.add(Numbers.format(robot.distance(), Numbers.MODEL));
            row.add(Integer.toString(robot.collisions()));
            row.add(Numbers.format(robot.firstCollisionTime(), Numbers.MODEL));
            row.add(Long.toString(robot.events()));
            for (String n : resultNames) {
                Double v = robot.results().get(n);
                row.add(v == null ? "" : Numbers.asReported(v));
            }
            row.addAll(end);
            rows.add(row);
        }
        return rows;
    }

    private static void pose(List<String> row, RobotResult.Pose p) {
        row.add(Numbers.format(p.x(), Numbers.MODEL));
        row.add(Numbers.format(p.y(), Numbers.MODEL));
        row.add(Numbers.format(p.heading(), Numbers.MODEL));
    }

    /** Rows as comma-separated text, a line feed after each. */
    static String text(List<List<String>> rows) {
        StringBuilder b = new StringBuilder();
        for (List<String> row : rows) {
            for (int i = 0; i < row.size(); i++) {
                b.append(i == 0 ? "" : ",").append(field(row.get(i)));
            }
            b.append('\n');
        }
        return b.toString();
    }

    /**
     * The runs {@code file} holds rows of, in the order of the file; none if there is no file. A last
     * row cut off while being written (the sweep was killed) is left out; the whole rows before it may
     * be the same run's first robots, which {@code --resume} checks against the run's folder.
     *
     * @param varied the varied keys the file must have columns for
     * @throws IOException naming the file and line if it is not a sweep's results
     */
    static List<Kept> read(Path file, List<String> varied) throws IOException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            return List.of();
        }
        List<List<String>> rows = CsvText.rows(text);
        Map<String, Integer> at = rows.isEmpty() ? Map.of() : columns(rows.get(0));
        for (String c : header(varied, List.of())) {
            if (!at.containsKey(c)) {
                throw new IOException(file + ": not this sweep's results (it has no column " + c + ")");
            }
        }
        List<String> results = new ArrayList<>();
        for (String c : rows.get(0)) {
            if (c.startsWith(RESULT_PREFIX)) {
                results.add(c.substring(RESULT_PREFIX.length()));
            }
        }
        List<Kept> kept = new ArrayList<>();
        List<RobotResult> robots = new ArrayList<>();
        for (int i = 1; i < rows.size(); i++) {
            Row row = new Row(rows.get(i), at);
            try {
                if (rows.get(i).size() != at.size()) {
                    throw new IllegalArgumentException(rows.get(i).size() + " columns instead of " + at.size());
                }
                if (!row.get("robot").isEmpty()) {
                    robots.add(row.robot(results));
                }
                if (i + 1 == rows.size() || !row.sameRun(new Row(rows.get(i + 1), at), varied)) {
                    RunReport report = new RunReport(row.real("end_time"), row.get("reason"),
                            Integer.parseInt(row.get("status")), robots);
                    kept.add(new Kept(row.configuration(varied), Long.parseLong(row.get("seed")), row.get("plan"),
                            report, row.real("wall_seconds")));
                    robots.clear();
                }
            } catch (IllegalArgumentException e) {
                throw new IOException(file + ": row " + (i + 1) + " is not a sweep's result: " + e.getMessage(), e);
            }
        }
        return kept;
    }

    private static Map<String, Integer> columns(List<String> header) {
        Map<String, Integer> at = new HashMap<>();
        for (int i = 0; i < header.size(); i++) {
            at.put(header.get(i), i);
        }
        return at;
    }

    /** A row read back, its fields by column name. */
    private record Row(List<String> fields, Map<String, Integer> at) {
        String get(String column) {
            Integer i = at.get(column);
            return i == null || i >= fields.size() ? "" : fields.get(i);
        }

        double real(String column) {
            String v = get(column);
            return v.isEmpty() ? Double.NaN : Double.parseDouble(v);
        }

        RobotResult.Pose pose(String prefix) {
            return new RobotResult.Pose(real(prefix + "x"), real(prefix + "y"), real(prefix + "heading"));
        }

        RobotResult robot(List<String> results) {
            Map<String, Double> own = new LinkedHashMap<>();
            for (String n : results) {
                if (!get(RESULT_PREFIX + n).isEmpty()) {
                    own.put(n, real(RESULT_PREFIX + n));
                }
            }
            return new RobotResult(get("robot"), pose("start_"), pose("end_"), real("distance"),
                    Integer.parseInt(get("collisions")), real("first_collision_time"), Long.parseLong(get("events")), own);
        }

        Map<String, String> configuration(List<String> varied) {
            Map<String, String> c = new LinkedHashMap<>();
            varied.forEach(k -> c.put(k, get(k)));
            return c;
        }

        /** Rows of the same run: the same configuration, seed and plan. */
        boolean sameRun(Row other, List<String> varied) {
            return other.fields.size() > 1 && get("seed").equals(other.get("seed"))
                    && get("plan").equals(other.get("plan")) && configuration(varied).equals(other.configuration(varied));
        }
    }

    /** A text field, quoted if it holds a comma, a quote or a line break. */
    static String field(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
