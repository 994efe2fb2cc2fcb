package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Sweep;
import rp1.simulator.launch.JavaCommand;

/**
 * A sweep stopped by a signal keeps the runs it finished, stops the others cleanly and says how to go
 * on; {@code --resume} then runs only what is missing, and only for the same sweep.
 */
@Timeout(120)
class InterruptedSweepTest {
    @TempDir
    Path dir;
    private final InProcessSweep sweeps = new InProcessSweep();

    /** Runs of a simulated second at real speed: each takes a second or two of wall time. */
    private String[] sweep(String seeds, String... more) throws IOException {
        Files.write(dir.resolve("home.txt"), List.of("caption: \"with home\";", "wall w { geometry: 0, 0, 4, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"), StandardCharsets.UTF_8);
        Files.write(dir.resolve("slow.ini"), List.of("floorPlanFileName=" + dir.resolve("home.txt"), "enableGUI=false",
                "enableNetworkClients=false", "simulationSpeed=1", "maxSimulationTime=1", "dlcEnabled=true",
                "dlcName=" + SleepyDlc.class.getName()), StandardCharsets.UTF_8);
        List<String> args = new ArrayList<>(List.of("-p", dir.resolve("slow.ini").toString(), "--seeds", seeds,
                "--jobs", "1", "--out", dir.resolve("out").toString()));
        args.addAll(List.of(more));
        return args.toArray(new String[0]);
    }

    private int inProcess(String... args) {
        return sweeps.run(args);
    }

    /** results.csv has a row for each of seeds 1 to {@code seeds}, in order, each run ended at its time limit. */
    private void assertEveryRunEndedAsAsked(int seeds) throws IOException {
        List<String> rows = rows();
        assertEquals(seeds + 1, rows.size(), rows.toString());
        for (int seed = 1; seed <= seeds; seed++) {
            assertTrue(rows.get(seed).startsWith(seed + "," + dir.resolve("home.txt") + ",runs/" + seed + "-home,")
                    && rows.get(seed).contains(",0,max-simulation-time,"), rows.get(seed));
        }
    }

    private List<String> rows() throws IOException {
        Path results = dir.resolve("out/results.csv");
        return Files.exists(results) ? Files.readAllLines(results, StandardCharsets.UTF_8) : List.of();
    }

    @Test
    void aSweepStoppedBySigtermKeepsItsFinishedRunsAndResumeRunsOnlyTheOthers() throws Exception {
        String[] args = sweep("1-4");
        Process sweep = new ProcessBuilder(JavaCommand.of(List.of(), Sweep.class.getName(), args))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve("sweep.txt").toFile()).start();
        Path second = dir.resolve("out/runs/2-home");
        try {
            // results.csv has the first run's row as soon as it ends; stop while the second one runs.
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!(rows().size() == 2 && Files.exists(second.resolve("recording.txt.part")))) {
                assertTrue(System.nanoTime() < deadline && sweep.isAlive(), "the first run ends, the second starts: "
                        + rows() + Files.readString(dir.resolve("sweep.txt")));
                Thread.sleep(20);
            }
            sweep.destroy();
            assertTrue(sweep.waitFor(60, TimeUnit.SECONDS), "the sweep stops");
        } finally {
            sweep.destroyForcibly();
        }
        String said = Files.readString(dir.resolve("sweep.txt"));
        assertEquals(130, sweep.exitValue(), said);
        assertTrue(said.contains("rp1.Sweep: interrupted; 1 of 4 runs finished (0 failed), in "
                + dir.resolve("out/results.csv") + " and " + dir.resolve("out/summary.png") + ". To run the other 3, add"
                + " --resume to the same command:\n  java rp1.Sweep " + String.join(" ", args) + " --resume"), said);
        List<String> rows = rows();
        assertEquals(2, rows.size(), rows.toString());
        assertTrue(rows.get(1).startsWith("1," + dir.resolve("home.txt") + ",runs/1-home,") && rows.get(1)
                .contains(",0,max-simulation-time,"), rows.get(1));
        assertTrue(Files.exists(dir.resolve("out/summary.png")));
        assertTrue(Files.readString(second.resolve("recording.txt")).contains("\nend "),
                "the run that was stopped closed its recording");
        assertFalse(Files.exists(dir.resolve("out/runs/3-home")), "no run was started after the signal");

        FileTime firstRun = Files.getLastModifiedTime(dir.resolve("out/runs/1-home/" + RunReport.FILE));
        assertEquals(0, inProcess(sweep("1-4", "--resume")), sweeps.out() + sweeps.err());
        assertTrue(sweeps.out().contains("; 1 finished before, 3 to run"), sweeps.out());
        assertEquals(firstRun, Files.getLastModifiedTime(dir.resolve("out/runs/1-home/" + RunReport.FILE)),
                "the run that had finished was not run again");
        assertEveryRunEndedAsAsked(4);
    }

    @Test
    void resumeRunsAgainARunThatWasNotCarriedOutAndKeepsTheOthers() throws Exception {
        assertEquals(0, inProcess(sweep("1-3")), sweeps.out() + sweeps.err());
        // As a cluster leaves the row of a run it lost (rp1-spark): no results, the reason, status 1.
        List<String> rows = new ArrayList<>(rows());
        List<String> header = List.of(rows.get(0).split(",", -1));
        List<String> lost = new ArrayList<>(List.of(rows.get(2).split(",", -1)));
        lost.set(header.indexOf("reason"), RunReport.LOST_BY_CLUSTER + "executor 1 lost");
        lost.set(header.indexOf("status"), "1");
        rows.set(2, String.join(",", lost));
        Files.write(dir.resolve("out/results.csv"), rows, StandardCharsets.UTF_8);
        FileTime first = Files.getLastModifiedTime(dir.resolve("out/runs/1-home/" + RunReport.FILE));
        FileTime third = Files.getLastModifiedTime(dir.resolve("out/runs/3-home/" + RunReport.FILE));

        assertEquals(0, inProcess(sweep("1-3", "--resume")), sweeps.out() + sweeps.err());
        assertTrue(sweeps.out().contains("; 2 finished before, 1 to run"), sweeps.out());
        assertEquals(first, Files.getLastModifiedTime(dir.resolve("out/runs/1-home/" + RunReport.FILE)));
        assertEquals(third, Files.getLastModifiedTime(dir.resolve("out/runs/3-home/" + RunReport.FILE)));
        assertEveryRunEndedAsAsked(3);
    }

    @Test
    void aRunThatCouldNotStartIsARowTheSweepSaysHowToRunAgain() throws Exception {
        // The second run to go again, and a file where its folder should be: it cannot be started.
        assertEquals(0, inProcess(sweep("1-3")), sweeps.out() + sweeps.err());
        List<String> rows = new ArrayList<>(rows());
        rows.remove(2);
        Files.write(dir.resolve("out/results.csv"), rows, StandardCharsets.UTF_8);
        try (Stream<Path> files = Files.walk(dir.resolve("out/runs/2-home"))) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        }
        Files.writeString(dir.resolve("out/runs/2-home"), "in the way");
        String[] args = sweep("1-3", "--resume");
        assertEquals(Sweep.RUN_FAILED, inProcess(args), sweeps.out() + sweeps.err());
        assertTrue(rows().get(2).contains(RunReport.NOT_STARTED), rows().get(2));
        assertTrue(sweeps.err().contains("rp1.Sweep: 1 of the failed runs was never carried out (not started, or lost"
                + " by the cluster; results.csv says why). To run it again, add --resume to the same command:\n  java rp1.Sweep "
                + String.join(" ", args)), sweeps.err());

        Files.delete(dir.resolve("out/runs/2-home"));
        assertEquals(0, inProcess(sweep("1-3", "--resume")), sweeps.out() + sweeps.err());
        assertTrue(sweeps.out().contains("; 2 finished before, 1 to run"), sweeps.out());
        assertTrue(rows().get(2).contains(",0,max-simulation-time,"), rows().get(2));
    }

    @Test
    void resumeRefusesAFolderOfAnotherSweepSayingWhatDiffers() throws Exception {
        assertEquals(0, inProcess(sweep("1")), sweeps.out() + sweeps.err());
        List<String> before = rows();

        assertEquals(1, inProcess(sweep("1-2", "--resume")));
        assertEquals("rp1.Sweep: --resume: " + dir.resolve("out") + " holds another sweep (sweep.ini): the seeds"
                + " (--seeds): 1 there, 1,2 here. Resume it with its own options, or give another --out\n",
                sweeps.err());
        assertEquals(before, rows(), "nothing was run");
    }

    @Test
    void resumeRefusesAFolderWithoutASweep() throws Exception {
        Files.createDirectories(dir.resolve("out"));
        assertEquals(1, inProcess(sweep("1", "--resume")));
        assertEquals("rp1.Sweep: --resume: " + dir.resolve("out") + " holds no sweep to go on with (it has no"
                + " sweep.ini)\n", sweeps.err());
    }
}
