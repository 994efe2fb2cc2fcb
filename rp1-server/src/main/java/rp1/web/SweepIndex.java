package rp1.web;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.io.WholeFiles;
import rp1.simulator.record.RecordingException;

/**
 * A sweep's {@code index.html} (docs/guide.md, "Running many"): the summary per configuration (the
 * sweep's {@code summary.csv} if it wrote one, else the runs and failures per plan), a table of every
 * run as {@code results.csv} has it, sortable by any column, and from each run a link to its replay
 * page ({@code replay.html} in the run's folder, written here when asked for, else the command that writes
 * it). It reads only the sweep's files, so it follows whatever columns they have.
 */
public final class SweepIndex {
    /** The name of the index in the sweep's folder. */
    public static final String NAME = "index.html";
    /** The name of a run's replay page in its folder. */
    public static final String PAGE = "replay.html";

    private SweepIndex() {
    }

    /**
     * Writes {@code index.html} into the sweep's folder {@code out}, first writing the replay page of
     * every run that has a recording and no page yet if {@code pages}.
     *
     * @return the runs whose page could not be written, with why (empty when all were)
     */
    public static List<String> write(Path out, boolean pages) throws IOException {
        return write(out, pages, Files.exists(out.resolve("summary.png")));
    }

    /**
     * {@link #write(Path, boolean)}, showing {@code summary.png} if {@code picture}: a sweep writes its
     * index while the picture is still being put together.
     */
    public static List<String> write(Path out, boolean pages, boolean picture) throws IOException {
        CsvTable results = CsvTable.read(out.resolve("results.csv"));
        Path summaryFile = out.resolve("summary.csv");
        CsvTable summary = Files.exists(summaryFile) ? CsvTable.read(summaryFile) : perPlan(results);
        List<String> failures = new ArrayList<>();
        Json runs = new Json().beginArray();
        for (List<String> row : results.rows()) {
            String folder = runFolder(out, results.value(row, "run"), results.value(row, "seed"), results.value(row, "plan"));
            if (pages && folder != null) {
                writePage(out.resolve(folder), failures);
            }
            runs.beginObject().key("cells").beginArray();
            for (String cell : row) {
                runs.value(cell);
            }
            runs.endArray().key("folder").value(folder)
                    .key("page").value(folder != null && Files.exists(out.resolve(folder).resolve(PAGE))).endObject();
        }
        String data = new Json().beginObject().key("summary").raw(table(summary)).key("header").raw(strings(results.header()))
                .key("runs").raw(runs.endArray().toString()).key("picture").value(picture).key("out").value(out.toAbsolutePath().toString())
                .endObject().toString();
        String html = template().replace("/*RP1-DATA*/", data);
        Path index = out.resolve(NAME);
        WholeFiles.writeString(index, html);
        return failures;
    }

    /**
     * The run's folder: the results' {@code run} column, or else (a sweep of an older version) under
     * {@code runs/} as SEED-PLAN, the plan without its extension; null if there is none.
     */
    private static String runFolder(Path out, String run, String seed, String plan) {
        String name = plan.replaceAll("\\.[^./\\\\]*$", "").replaceAll(".*[/\\\\]", "");
        String folder = run.isEmpty() ? "runs/" + seed + "-" + name : run;
        return Files.isDirectory(out.resolve(folder)) ? folder : null;
    }

    private static void writePage(Path run, List<String> failures) {
        Path recording = run.resolve("recording.txt");
        if (!Files.exists(recording) || Files.exists(run.resolve(PAGE))) {
            return;
        }
        try {
            ReplayPage.write(recording, run.getFileName().toString(), run.resolve(PAGE));
        } catch (RecordingException | IOException e) {
            failures.add(run + ": " + e.getMessage());
        }
    }

    /** Without a summary.csv: per plan, the runs and how many failed (a nonzero exit status). */
    private static CsvTable perPlan(CsvTable results) {
        Map<String, int[]> counts = new LinkedHashMap<>();
        Map<String, Set<String>> seen = new LinkedHashMap<>();
        for (List<String> row : results.rows()) {
            String plan = results.value(row, "plan");
            String run = results.value(row, "seed");
            int[] c = counts.computeIfAbsent(plan, p -> new int[2]);
            if (seen.computeIfAbsent(plan, p -> new HashSet<>()).add(run)) {
                c[0]++;
                if (!results.value(row, results.header().contains("status") ? "status" : "exit_status").equals("0")) {
                    c[1]++;
                }
            }
        }
        List<List<String>> rows = new ArrayList<>();
        counts.forEach((plan, c) -> rows.add(List.of(plan, Integer.toString(c[0]), Integer.toString(c[1]))));
        return new CsvTable(List.of("plan", "runs", "failed"), rows);
    }

    private static String table(CsvTable t) {
        Json j = new Json().beginObject().key("header").raw(strings(t.header())).key("rows").beginArray();
        for (List<String> row : t.rows()) {
            j.raw(strings(row));
        }
        return j.endArray().endObject().toString();
    }

    private static String strings(List<String> values) {
        Json j = new Json().beginArray();
        for (String v : values) {
            j.value(v);
        }
        return j.endArray().toString();
    }

    private static String template() throws IOException {
        try (InputStream in = SweepIndex.class.getResourceAsStream("sweep-index.html")) {
            if (in == null) {
                throw new IOException("rp1/web/sweep-index.html is missing from the class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
