package rp1.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Sweep;
import rp1.simulator.batch.Interruption;

/**
 * The same sweep of the bumper car on the sweep's own engine, on Spark's {@code local[2]} and on a
 * two-worker standalone cluster ({@link Cluster}) gives the same rows, wall times aside; and a worker
 * killed in the middle of a sweep costs no run and repeats none.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
@Timeout(300)
class SparkSweepTest {
    private static final int RUNS = 32;

    @TempDir
    static Path dir;
    private Path properties;
    private List<String> local;
    private Cluster cluster;
    private CompletableFuture<Cluster> starting;

    @BeforeAll
    void localEngineAndCluster() throws Exception {
        // Short runs: the bumper car for 20 simulated seconds, each a fifth of a second longer in wall
        // time than it needs (SlowBumper), so that a worker killed after five runs leaves some to do.
        String bumper = new String(getClass().getResourceAsStream("/Properties/bumper.ini").readAllBytes(),
                StandardCharsets.UTF_8);
        properties = Files.writeString(dir.resolve("short.ini"), bumper
                + "\nmaxSimulationTime=20\ndlcName=" + SlowBumper.class.getName() + "\n");
        starting = CompletableFuture.supplyAsync(() -> {
            try {
                return Cluster.start(2, 1, "1g", dir.resolve("cluster"));
            } catch (IOException | InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
        local = rows(sweep(null, "1-" + RUNS, "local"));
        cluster = starting.get(120, TimeUnit.SECONDS);
    }

    @AfterAll
    void stopCluster() throws Exception {
        starting.get(120, TimeUnit.SECONDS).close();
    }

    @Test
    void sparkInThisProcessGivesTheRowsOfTheSweepsOwnEngine() throws Exception {
        assertEquals(local.subList(0, 17), rows(sweep("local[2]", "1-16", "local2")));
    }

    @Test
    void aTwoWorkerClusterGivesTheRowsOfTheSweepsOwnEngineAndBringsTheRunsFilesBack() throws Exception {
        Path out = sweep(cluster.masterUrl(), "1-16", "on-the-cluster");
        assertEquals(local.subList(0, 17), rows(out));
        Path run = out.resolve("runs/3-contest");
        for (String f : List.of("recording.txt", "events.txt", "result.txt", "server.log")) {
            assertTrue(Files.size(run.resolve(f)) > 0, f + " came back from the executor");
        }
        assertTrue(Files.readString(run.resolve("executor.txt")).strip().length() > 0, "the executor's host is named");
    }

    /** Last: it leaves the cluster one worker. */
    @Test
    @Order(Integer.MAX_VALUE)
    void aWorkerKilledInTheMiddleOfASweepCostsNoRunAndRepeatsNone() throws Exception {
        Path out = dir.resolve("killed");
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(text, true, StandardCharsets.UTF_8);
        CompletableFuture<Integer> sweep = CompletableFuture.supplyAsync(() -> SparkSweep.run(args(cluster.masterUrl(),
                "1-" + RUNS, out), print, print, false, new Interruption()));
        Path results = out.resolve("results.csv");
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while ((!Files.exists(results) || Files.readAllLines(results).size() < 5) && !sweep.isDone()
                && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        // A sweep that ended (or never wrote a row) before the worker could be killed says why, with the
        // cluster's logs, rather than failing on a missing file.
        assertTrue(!sweep.isDone() && Files.exists(results) && Files.readAllLines(results).size() < RUNS,
                () -> "the worker is to be killed while runs are left, but the sweep "
                        + (sweep.isDone() ? "ended with status " + sweep.join() : "wrote " + results + " too late")
                        + ":\n" + text.toString(StandardCharsets.UTF_8) + clusterLogs());
        cluster.killWorker(1);
        int status = sweep.get(240, TimeUnit.SECONDS);
        assertEquals(0, status, () -> text.toString(StandardCharsets.UTF_8) + clusterLogs());
        assertEquals(local, rows(out));
    }

    @Test
    void aRunThatFailsByItselfIsARowWithItsReasonOnSparkAsOnItsOwn() throws Exception {
        Path failing = Files.writeString(dir.resolve("failing.ini"), Files.readString(properties)
                + "dlcName=" + FailingRobot.class.getName() + "\n");
        List<String> own = rows(sweep(failing, null, "1-2", "failing-own", Sweep.RUN_FAILED));
        assertEquals(own, rows(sweep(failing, "local[2]", "1-2", "failing-spark", Sweep.RUN_FAILED)));
        assertEquals(3, own.size(), own.toString());
        assertTrue(own.get(1).contains("this robot always fails"), own.get(1));
    }

    @Test
    void aPlanWhoseWallsComeFromAMapImageIsRefusedBeforeAnyRunRatherThanFailingEveryRun() throws Exception {
        Path rooms = Path.of(System.getProperty("rp1.root", "..")).resolve("FloorPlans/rooms.yaml").toAbsolutePath();
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(text, true, StandardCharsets.UTF_8);
        List<String> a = new ArrayList<>(List.of(args("local[1]", "1", dir.resolve("map"))));
        a.addAll(List.of("--plans", rooms.toString()));
        int status = SparkSweep.run(a.toArray(new String[0]), print, print, false, new Interruption());
        assertEquals(1, status, text.toString(StandardCharsets.UTF_8));
        assertTrue(text.toString(StandardCharsets.UTF_8).contains("--plans " + rooms + ": a plan whose walls come from a"
                + " map image cannot go to a cluster yet"), text.toString(StandardCharsets.UTF_8));
    }

    private Path sweep(String master, String seeds, String name) {
        return sweep(properties, master, seeds, name, 0);
    }

    private Path sweep(Path ini, String master, String seeds, String name, int expected) {
        Path out = dir.resolve(name);
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(text, true, StandardCharsets.UTF_8);
        int status = master == null ? Sweep.run(args(ini, null, seeds, out), print, print, false)
                : SparkSweep.run(args(ini, master, seeds, out), print, print, false, new Interruption());
        assertEquals(expected, status, text.toString(StandardCharsets.UTF_8));
        return out;
    }

    private String[] args(String master, String seeds, Path out) {
        return args(properties, master, seeds, out);
    }

    private String[] args(Path ini, String master, String seeds, Path out) {
        List<String> a = new ArrayList<>(List.of("-p", ini.toString(), "--seeds", seeds, "--out", out.toString()));
        if (master != null) {
            a.addAll(List.of("--master", master));
        } else {
            a.addAll(List.of("--jobs", "2"));
        }
        return a.toArray(new String[0]);
    }

    /** The cluster's logs, for a failure's message. */
    private String clusterLogs() {
        return "\nThe master's log:\n" + log("master.log") + "\nThe first worker's log:\n" + log("worker-1.log")
                + "\nThe other worker's log:\n" + log("worker-2.log");
    }

    /** The last lines of a log of the cluster's, for a failure's message. */
    private String log(String name) {
        try {
            List<String> lines = Files.readAllLines(cluster.dir().resolve(name));
            return String.join("\n", lines.subList(Math.max(0, lines.size() - 200), lines.size()));
        } catch (IOException e) {
            return e.toString();
        }
    }

    /** The rows of results.csv without their wall-clock time, which no two runs share. */
    private static List<String> rows(Path out) throws IOException {
        List<String> lines = Files.readAllLines(out.resolve("results.csv"));
        int wall = Arrays.asList(lines.get(0).split(",")).indexOf("wall_seconds");
        List<String> rows = new ArrayList<>();
        for (String line : lines) {
            List<String> cells = new ArrayList<>(Arrays.asList(line.split(",", -1)));
            cells.remove(wall);
            rows.add(String.join(",", cells));
        }
        return rows;
    }
}
