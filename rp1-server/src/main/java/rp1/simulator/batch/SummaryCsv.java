package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import rp1.io.WholeFiles;

/**
 * A sweep's {@code summary.csv}: one row per configuration (the varied keys' values, the plan and the
 * robot) with how many runs it had and how many failed, and, for every numeric column of
 * {@code results.csv} but the headings, the {@link Statistics} of its values as written there in the
 * runs that ended as asked (status 0; empty fields, such as the first collision time of a robot that
 * never collided, are left out: {@code _n} says how many counted).
 */
public final class SummaryCsv {
    /** What each metric column gets, in order: {@code METRIC_n}, {@code METRIC_mean}, ... */
    public static final List<String> STATISTICS = List.of("n", "mean", "sd", "ci95", "min", "max");
    /**
     * The columns of results.csv that are not summed up: the run's identity, its outcome in words, and
     * the headings, angles whose mean and spread as plain numbers mean nothing (the mean of 3.1 and
     * -3.1 rad is 0, the opposite way).
     */
    private static final List<String> NOT_METRICS = List.of("seed", "plan", "run", "robot", "status", "reason",
            "start_heading", "end_heading");

    /** One configuration's row. */
    public record Row(Map<String, String> configuration, int runs, int failed, Map<String, Statistics> metrics) {
    }

    private SummaryCsv() {
    }

    /** The metrics of a results table: its numeric columns, less the varied keys and the run's identity. */
    public static List<String> metrics(List<String> header, List<String> varied) {
        List<String> m = new ArrayList<>();
        for (String c : header) {
            if (!varied.contains(c) && !NOT_METRICS.contains(c)) {
                m.add(c);
            }
        }
        return m;
    }

    /**
     * The rows of the summary of a results table, configurations in the order first seen.
     *
     * @param header the table's columns
     * @param rows   its rows
     * @param varied the varied keys
     */
    public static List<Row> summarize(List<String> header, List<List<String>> rows, List<String> varied) {
        List<String> group = new ArrayList<>(varied);
        group.add("plan");
        group.add("robot");
        List<String> metrics = metrics(header, varied);
        Map<Map<String, String>, List<List<String>>> byConfiguration = new LinkedHashMap<>();
        for (List<String> row : rows) {
            Map<String, String> key = new LinkedHashMap<>();
            group.forEach(g -> key.put(g, row.get(header.indexOf(g))));
            byConfiguration.computeIfAbsent(key, k -> new ArrayList<>()).add(row);
        }
        List<Row> out = new ArrayList<>();
        int status = header.indexOf("status");
        byConfiguration.forEach((key, members) -> {
            // A failed run's numbers are of a run that did not go as asked (a robot that crashed at 7 s
            // ended its minute early): they are counted in `failed`, not in the statistics.
            List<List<String>> succeeded = members.stream().filter(r -> "0".equals(r.get(status))).toList();
            Map<String, Statistics> stats = new LinkedHashMap<>();
            for (String m : metrics) {
                int at = header.indexOf(m);
                stats.put(m, Statistics.of(succeeded.stream().mapToDouble(r -> Numbers.parse(r.get(at)))
                        .filter(v -> !Double.isNaN(v)).toArray()));
            }
            int failed = members.size() - succeeded.size();
            out.add(new Row(key, members.size(), failed, stats));
        });
        return out;
    }

    /** The summary as a table: its header, then a row per configuration. */
    public static List<List<String>> table(List<Row> rows, List<String> metrics) {
        List<List<String>> table = new ArrayList<>();
        List<String> header = new ArrayList<>(rows.isEmpty() ? List.of() : rows.get(0).configuration().keySet());
        header.add("runs");
        header.add("failed");
        for (String m : metrics) {
            STATISTICS.forEach(s -> header.add(m + "_" + s));
        }
        table.add(header);
        for (Row r : rows) {
            List<String> line = new ArrayList<>(r.configuration().values());
            line.add(Integer.toString(r.runs()));
            line.add(Integer.toString(r.failed()));
            for (String m : metrics) {
                Statistics s = r.metrics().get(m);
                line.add(Integer.toString(s.n()));
                for (double v : new double[] {s.mean(), s.sd(), s.ci95(), s.min(), s.max()}) {
                    line.add(Numbers.statistic(v));
                }
            }
            table.add(line);
        }
        return table;
    }

    /**
     * Reads {@code results} and writes its summary into {@code file}, replacing it in one step.
     *
     * @return the summary's rows
     */
    public static List<Row> write(Path results, Path file, List<String> varied) throws IOException {
        List<List<String>> table = CsvText.rows(Files.readString(results, StandardCharsets.UTF_8));
        List<String> header = table.get(0);
        List<Row> rows = summarize(header, table.subList(1, table.size()), varied);
        WholeFiles.writeString(file, ResultsCsv.text(table(rows, metrics(header, varied))));
        return rows;
    }
}
