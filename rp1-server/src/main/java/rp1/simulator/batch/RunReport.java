package rp1.simulator.batch;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;

import rp1.simulator.outcome.RobotResult;

/**
 * How one run of a sweep ended, as its process leaves it in {@code result.txt} for the sweep to read:
 * the simulated time it stopped at, why, the server's exit status, and every robot's results.
 *
 * @param endTime    simulated seconds at the end (NaN if the run never started)
 * @param endReason  {@code max-simulation-time}, {@code clients-done}, {@code nobody-left} (every robot
 *                   and client left), {@code stopped}, or what went wrong
 * @param exitStatus the server's exit status (docs/guide.md section 4), or the process's
 * @param parametersAsked the run's parameters ({@code param.NAME}) its loaded robots asked for, by
 *                   name; null if that is not known (a {@code --client} program's run, a run that
 *                   did not start, a row read back from {@code results.csv})
 */
public record RunReport(double endTime, String endReason, int exitStatus, List<RobotResult> robots,
                        List<String> parametersAsked) {
    /** The status of a run stopped because it outlived the sweep's {@code --timeout}, as timeout(1) has it. */
    public static final int TIMED_OUT = 124;
    /** The file a run leaves in its folder. */
    public static final String FILE = "result.txt";

    /** Copies the lists. */
    public RunReport {
        robots = List.copyOf(robots);
        parametersAsked = parametersAsked == null ? null : List.copyOf(parametersAsked);
    }

    /** A report that does not know which parameters the robots asked for. */
    public RunReport(double endTime, String endReason, int exitStatus, List<RobotResult> robots) {
        this(endTime, endReason, exitStatus, robots, null);
    }

    /** The start of the reason of a run whose folder or process could not be made. */
    public static final String NOT_STARTED = "the run could not be started: ";
    /** The start of the reason of a run a cluster lost (its executors lost it, or the cluster ended the sweep's application). */
    public static final String LOST_BY_CLUSTER = "the cluster could not carry out the run: ";

    /** A run that did not get as far as reporting itself. */
    public static RunReport failed(String reason, int exitStatus) {
        return new RunReport(Double.NaN, reason, exitStatus, List.of());
    }

    /**
     * Whether the run was carried out, well or not: false if it could not be started or a cluster lost
     * it, which says nothing of the run itself, so {@code --resume} runs it again.
     */
    public boolean carriedOut() {
        return !(endReason.startsWith(NOT_STARTED) || endReason.startsWith(LOST_BY_CLUSTER));
    }

    /**
     * The report a run's process left in {@code dir}; if it left none, a failure with its exit status
     * and the last line it printed into {@code output}. Every engine says it this way, so that the
     * row is the same wherever the run ran.
     */
    public static RunReport ofProcess(Path dir, Path output, int status) {
        try {
            return read(dir);
        } catch (IOException e) {
            return failed("the run ended with status " + status + " and no results: " + lastLine(output), status);
        }
    }

    /** The last line a process printed into {@code file}, or what there is instead. */
    public static String lastLine(Path file) {
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
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

    /** Whether the run ended as its properties meant it to: status 0. */
    public boolean succeeded() {
        return exitStatus == 0;
    }

    /** Writes the report into {@code dir}. */
    public void write(Path dir) throws IOException {
        Map<String, String> p = new LinkedHashMap<>();
        p.put("end_time", Double.toString(endTime));
        p.put("end_reason", endReason);
        p.put("exit_status", Integer.toString(exitStatus));
        if (parametersAsked != null) {
            p.put("parameters_asked", String.join(",", parametersAsked));
        }
        p.put("robots", Integer.toString(robots.size()));
        for (int i = 0; i < robots.size(); i++) {
            RobotResult r = robots.get(i);
            String k = "robot." + (i + 1) + ".";
            p.put(k + "name", r.name());
            pose(p, k + "start.", r.start());
            pose(p, k + "end.", r.end());
            p.put(k + "distance", Double.toString(r.distance()));
            p.put(k + "collisions", Integer.toString(r.collisions()));
            p.put(k + "first_collision_time", Double.toString(r.firstCollisionTime()));
            p.put(k + "events", Long.toString(r.events()));
            p.put(k + "results", String.join(",", r.results().keySet()));
            r.results().forEach((name, value) -> p.put(k + "result." + name, Double.toString(value)));
        }
        Files.write(dir.resolve(FILE), PropertiesText.of(p).getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Reads the report a run left in {@code dir}.
     *
     * @throws IOException if there is none or it is not one
     */
    public static RunReport read(Path dir) throws IOException {
        Properties p = new Properties();
        try (Reader in = new StringReader(Files.readString(dir.resolve(FILE)))) {
            p.load(in);
        }
        try {
            List<RobotResult> robots = new ArrayList<>();
            int n = Integer.parseInt(required(p, "robots"));
            for (int i = 1; i <= n; i++) {
                String k = "robot." + i + ".";
                Map<String, Double> results = new LinkedHashMap<>();
                for (String name : required(p, k + "results").split(",")) {
                    if (!name.isEmpty()) {
                        results.put(name, real(p, k + "result." + name));
                    }
                }
                robots.add(new RobotResult(required(p, k + "name"), pose(p, k + "start."), pose(p, k + "end."),
                        real(p, k + "distance"), Integer.parseInt(required(p, k + "collisions")),
                        real(p, k + "first_collision_time"), Long.parseLong(required(p, k + "events")), results));
            }
            String asked = p.getProperty("parameters_asked");
            return new RunReport(real(p, "end_time"), required(p, "end_reason"),
                    Integer.parseInt(required(p, "exit_status")), robots,
                    asked == null ? null : asked.isEmpty() ? List.of() : List.of(asked.split(",")));
        } catch (NumberFormatException e) {
            throw new IOException(dir.resolve(FILE) + ": not a run's report: " + e.getMessage(), e);
        }
    }

    private static void pose(Map<String, String> p, String prefix, RobotResult.Pose pose) {
        p.put(prefix + "x", Double.toString(pose.x()));
        p.put(prefix + "y", Double.toString(pose.y()));
        p.put(prefix + "heading", Double.toString(pose.heading()));
    }

    private static RobotResult.Pose pose(Properties p, String prefix) throws IOException {
        return new RobotResult.Pose(real(p, prefix + "x"), real(p, prefix + "y"), real(p, prefix + "heading"));
    }

    private static String required(Properties p, String key) throws IOException {
        String v = p.getProperty(key);
        if (v == null) {
            throw new IOException("a run's report without " + key);
        }
        return v;
    }

    private static double real(Properties p, String key) throws IOException {
        return Double.parseDouble(required(p, key));
    }
}
