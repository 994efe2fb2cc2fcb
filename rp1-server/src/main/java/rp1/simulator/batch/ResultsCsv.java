package rp1.simulator.batch;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A sweep's {@code results.csv}: one row per run and robot. While the sweep goes, a run's rows are
 * appended (and on disk) as soon as it ends, so an interrupted sweep keeps what it finished; at the
 * end the file is rewritten whole with the runs in the order they were listed.
 */
public final class ResultsCsv implements AutoCloseable {
    /** The header row. */
    public static final String HEADER =
            "seed,plan,robot,end_time,end_reason,exit_status,x,y,heading,distance,collisions,events,wall_seconds";
    private static final int COLUMNS = 13;

    /** A run's rows read back: the run, how it ended, and its wall-clock time. */
    record Kept(long seed, String plan, RunReport report, double wallSeconds) {
    }

    private final OutputStream out;

    private ResultsCsv(OutputStream out) {
        this.out = out;
    }

    /**
     * Starts {@code file} afresh with the header and the rows of {@code kept} (the runs an earlier
     * sweep finished), then keeps it open for {@link #add}.
     */
    static ResultsCsv start(Path file, List<Batch.Outcome> kept) throws IOException {
        write(file, kept);
        return new ResultsCsv(Files.newOutputStream(file, StandardOpenOption.APPEND));
    }

    /** Appends the rows of a run that has ended; they are on disk when this returns. */
    synchronized void add(Batch.Outcome outcome) throws IOException {
        out.write(rows(outcome).getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    @Override
    public synchronized void close() throws IOException {
        out.close();
    }

    /** Writes the rows of {@code outcomes} into {@code file}, replacing it in one step. */
    public static void write(Path file, List<Batch.Outcome> outcomes) throws IOException {
        StringBuilder b = new StringBuilder(HEADER).append('\n');
        for (Batch.Outcome o : outcomes) {
            b.append(rows(o));
        }
        Path part = file.resolveSibling(file.getFileName() + ".part");
        Files.write(part, b.toString().getBytes(StandardCharsets.UTF_8));
        Files.move(part, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
    }

    private static String rows(Batch.Outcome o) {
        StringBuilder b = new StringBuilder();
        RunReport r = o.report();
        String start = o.run().seed() + "," + field(o.run().plan()) + ",";
        String run = "," + number(r.endTime()) + "," + field(r.endReason()) + "," + r.exitStatus() + ",";
        String wall = "," + String.format(Locale.ROOT, "%.3f", o.wallSeconds());
        if (r.robots().isEmpty()) {
            b.append(start).append(run).append(",,,,,").append(wall).append('\n');
        }
        for (RobotResult robot : r.robots()) {
            b.append(start).append(field(robot.name())).append(run)
                    .append(number(robot.x())).append(',').append(number(robot.y())).append(',')
                    .append(number(robot.heading())).append(',').append(number(robot.distance())).append(',')
                    .append(robot.collisions()).append(',').append(robot.events()).append(wall).append('\n');
        }
        return b.toString();
    }

    /**
     * The runs {@code file} holds rows of, in the order of the file; none if there is no file. A last
     * row cut off while being written (the sweep was killed) is left out: its run is run again.
     *
     * @throws IOException naming the file and line if it is not a sweep's results
     */
    static List<Kept> read(Path file) throws IOException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            return List.of();
        }
        List<List<String>> rows = CsvText.rows(text);
        if (rows.isEmpty() || !String.join(",", rows.get(0)).equals(HEADER)) {
            throw new IOException(file + ": not a sweep's results (its first line must be " + HEADER + ")");
        }
        List<Kept> kept = new ArrayList<>();
        List<RobotResult> robots = new ArrayList<>();
        for (int i = 1; i < rows.size(); i++) {
            List<String> row = rows.get(i);
            try {
                if (row.size() != COLUMNS) {
                    throw new IllegalArgumentException(row.size() + " columns instead of " + COLUMNS);
                }
                if (!row.get(2).isEmpty()) {
                    robots.add(new RobotResult(row.get(2), Double.parseDouble(row.get(6)), Double.parseDouble(row.get(7)),
                            Double.parseDouble(row.get(8)), Double.parseDouble(row.get(9)), Integer.parseInt(row.get(10)),
                            Long.parseLong(row.get(11))));
                }
                if (i + 1 == rows.size() || !sameRun(row, rows.get(i + 1))) {
                    RunReport report = new RunReport(row.get(3).isEmpty() ? Double.NaN : Double.parseDouble(row.get(3)),
                            row.get(4), Integer.parseInt(row.get(5)), robots);
                    kept.add(new Kept(Long.parseLong(row.get(0)), row.get(1), report, Double.parseDouble(row.get(12))));
                    robots.clear();
                }
            } catch (IllegalArgumentException e) {
                throw new IOException(file + ": row " + (i + 1) + " is not a sweep's result: " + e.getMessage(), e);
            }
        }
        return kept;
    }

    /** Rows of the same run: the same seed and plan. */
    private static boolean sameRun(List<String> a, List<String> b) {
        return b.size() > 1 && a.get(0).equals(b.get(0)) && a.get(1).equals(b.get(1));
    }

    private static String number(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    /** A text field, quoted if it holds a comma, a quote or a line break. */
    private static String field(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
