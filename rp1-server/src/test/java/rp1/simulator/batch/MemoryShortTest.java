package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.planparser.ParsedPlans;
import rp1.simulator.launch.JavaCommand;

/**
 * Runs in a sweep's process share its heap: a robot that keeps memory without end must not fail the
 * runs beside it, nor leave the sweep crawling while the collector works on a full heap. The runs
 * going when memory runs short are carried out again in processes of their own, as is every run after
 * them, and each row is the one the run has in a process of its own.
 */
@Timeout(180)
class MemoryShortTest {
    @TempDir
    Path dir;

    @Test
    void aRobotThatFillsTheSweepsHeapFailsNoRunAndEveryRowIsAsInProcessesOfTheirOwn() throws Exception {
        Path p = HomeSweep.properties(dir, "hog", HogDlc.class);
        // The sweep's process gets 64 MB, less than the hog of seed 2 keeps; a run's process gets the JVM's default.
        Path out = dir.resolve("shared");
        Process sweep = new ProcessBuilder(JavaCommand.of(List.of("-Xmx64m", "-XX:+UseParallelGC"), "rp1.Sweep",
                "-p", p.toString(), "--seeds", "1-4", "--jobs", "2", "--out", out.toString()))
                .redirectErrorStream(true).redirectOutput(dir.resolve("sweep.txt").toFile()).start();
        assertTrue(sweep.waitFor(150, TimeUnit.SECONDS), "the sweep still runs");
        String printed = Files.readString(dir.resolve("sweep.txt"));
        assertEquals(0, sweep.exitValue(), printed);
        assertTrue(printed.contains("was carried out again in a process of its own"), printed);

        InProcessSweep reference = new InProcessSweep();
        assertEquals(0, reference.run("-p", p.toString(), "--seeds", "1-4", "--jobs", "2", "--isolation", "process",
                "--out", dir.resolve("processes").toString()), reference.out() + reference.err());
        List<String> rows = withoutWallTime(out.resolve("results.csv"));
        assertEquals(withoutWallTime(dir.resolve("processes/results.csv")), rows);
        int status = List.of(rows.get(0).split(",")).indexOf("status");
        assertEquals(5, rows.size(), String.join("\n", rows));
        for (String row : rows.subList(1, rows.size())) {
            assertEquals("0", row.split(",")[status], row);
        }
    }

    @Test
    void aRunGoingWhenMemoryRunsShortIsCarriedOutAgainInAProcessOfItsOwnAndSoAreTheRunsAfterIt() throws Exception {
        // Two simulated seconds in real time: still going when the test says memory ran short.
        Files.write(dir.resolve("home.txt"), List.of("wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"));
        String properties = String.join("\n", "floorPlanFileName=" + dir.resolve("home.txt"), "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=1", "dlcEnabled=true",
                "dlcName=" + HogDlc.class.getName(), "maxSimulationTime=2");
        RunFolder folders = new RunFolder(properties, null, false);
        Batch.Run first = new Batch.Run(Map.of(), 1, dir.resolve("home.txt").toString(), dir.resolve("runs/1-home"));
        Batch.Run second = new Batch.Run(Map.of(), 3, dir.resolve("home.txt").toString(), dir.resolve("runs/3-home"));
        folders.prepare(first);
        folders.prepare(second);
        LoaderRuns engine = new LoaderRuns(List.of(HogDlc.class.getName()), getClass().getClassLoader(), 60,
                new ParsedPlans(), () -> RunEngine.inProcesses(60, List.of()));
        try {
            CompletableFuture<RunEngine.Ran> going = CompletableFuture.supplyAsync(() -> {
                try {
                    return engine.run(first);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!engine.anyRunning() && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertTrue(engine.anyRunning(), "the run has not begun");
            engine.memoryShort();
            RunEngine.Ran ran = going.get(60, TimeUnit.SECONDS);
            assertEquals("max-simulation-time", ran.report().endReason(), "carried out to its end elsewhere");
            assertTrue(Files.exists(first.dir().resolve(ProcessRuns.OUTPUT)), "in a process of its own");

            assertEquals("max-simulation-time", engine.run(second).report().endReason());
            assertTrue(Files.exists(second.dir().resolve(ProcessRuns.OUTPUT)), "the run after it too");
            String note = engine.note();
            assertTrue(note.contains("the sweep's process ran short of memory"), note);
            assertTrue(note.contains("1-home was carried out again in a process of its own: memory ran short while it went"),
                    note);
            assertFalse(note.contains("3-home was carried out again"), note);
        } finally {
            engine.close();
        }
    }

    @Test
    void aGuardWhoseOwnerIsGoneStopsLooking() throws Exception {
        // As a sweep that failed leaves its engine unclosed: the guard must not look on for ever.
        MemoryGuard<Object> guard = new MemoryGuard<>(new Object(), owner -> { });
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (guard.isLooking() && System.nanoTime() < deadline) {
            System.gc();
            Thread.sleep(60);
        }
        assertFalse(guard.isLooking());
        MemoryGuard<Path> kept = new MemoryGuard<>(dir, owner -> { });
        Thread.sleep(200);
        assertTrue(kept.isLooking(), "an owner still held keeps it looking");
        kept.close();
    }

    @Test
    void theOldestGenerationIsShortWhenACollectionLeavesItMoreThanFullToTheMark() {
        assertFalse(MemoryGuard.isShort(84, 100));
        assertFalse(MemoryGuard.isShort(85, 100));
        assertTrue(MemoryGuard.isShort(86, 100));
        assertFalse(MemoryGuard.isShort(1, 0), "no maximum known: never short");
    }

    @Test
    void theMemorySetAsideForTheRunsStopsIsAThirtySecondOfTheHeapAndAtMostFourMegabytes() {
        assertEquals(2 << 20, MemoryGuard.reserveFor(64L << 20));
        assertEquals(4 << 20, MemoryGuard.reserveFor(1L << 30));
        assertEquals(4 << 20, MemoryGuard.reserveFor(Long.MAX_VALUE), "no maximum: the most");
        assertEquals(0, MemoryGuard.reserveFor(0));
    }

    /** The rows of a results.csv without their last column, wall_seconds, which no two sweeps share. */
    private static List<String> withoutWallTime(Path csv) throws Exception {
        List<String> rows = new ArrayList<>();
        for (String row : Files.readAllLines(csv)) {
            rows.add(row.substring(0, row.lastIndexOf(',')));
        }
        return rows;
    }
}
