package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep killed while it appends a run's rows to results.csv (kill -9, the machine off) leaves them
 * cut short, in the middle of a row or between two robots' rows of a run of several robots. {@code
 * --resume} then runs that run again instead of keeping part of it, or refusing to go on.
 */
@Timeout(120)
class CutResultsTest {
    @TempDir
    Path dir;

    /** Two robots a run, three seeds, as fast as they compute; returns the arguments (with {@code more}). */
    private String[] sweep(String... more) throws Exception {
        Files.write(dir.resolve("two.txt"), List.of("wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }", "placement yard { geometry: 3, 1, 0, 0.2; }"));
        Files.write(dir.resolve("two.ini"), List.of("floorPlanFileName=" + dir.resolve("two.txt"), "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max", "dlcEnabled=true",
                "dlcName=" + HogDlc.class.getName() + "," + YardDlc.class.getName(), "maxSimulationTime=3"));
        List<String> args = new ArrayList<>(List.of("-p", dir.resolve("two.ini").toString(), "--seeds", "1,3,4",
                "--jobs", "1", "--out", dir.resolve("out").toString()));
        args.addAll(List.of(more));
        return args.toArray(new String[0]);
    }

    private String results() throws Exception {
        return Files.readString(dir.resolve("out/results.csv"), StandardCharsets.UTF_8);
    }

    /** The rows without their last column, wall_seconds, which no two sweeps share. */
    private static List<String> withoutWallTime(String csv) {
        List<String> rows = new ArrayList<>();
        for (String row : csv.split("\n")) {
            rows.add(row.substring(0, row.lastIndexOf(',')));
        }
        return rows;
    }

    /** Cuts results.csv {@code back} characters before its end, resumes, and compares with the whole sweep. */
    private void cutAndResume(int back) throws Exception {
        InProcessSweep sweeps = new InProcessSweep();
        assertEquals(0, sweeps.run(sweep()), sweeps.out() + sweeps.err());
        String whole = results();
        assertEquals(7, whole.split("\n").length, "a row per robot: " + whole);
        Files.writeString(dir.resolve("out/results.csv"), whole.substring(0, whole.length() - back), StandardCharsets.UTF_8);

        sweeps.reset();
        assertEquals(0, sweeps.run(sweep("--resume")), sweeps.out() + sweeps.err());
        assertTrue(sweeps.out().contains("; 2 finished before, 1 to run"), sweeps.out());
        assertEquals(withoutWallTime(whole), withoutWallTime(results()));
    }

    @Test
    void aRowCutInTheMiddleLosesItsWholeRunWhichRunsAgain() throws Exception {
        cutAndResume(9);
    }

    @Test
    void rowsCutBetweenTwoRobotsOfARunLoseTheRunWhichRunsAgain() throws Exception {
        InProcessSweep sweeps = new InProcessSweep();
        assertEquals(0, sweeps.run(sweep()), sweeps.out() + sweeps.err());
        String whole = results();
        String last = whole.substring(whole.lastIndexOf('\n', whole.length() - 2) + 1);
        Files.deleteIfExists(dir.resolve("out/results.csv"));
        Files.writeString(dir.resolve("out/results.csv"), whole.substring(0, whole.length() - last.length()),
                StandardCharsets.UTF_8);

        sweeps.reset();
        assertEquals(0, sweeps.run(sweep("--resume")), sweeps.out() + sweeps.err());
        assertTrue(sweeps.out().contains("; 2 finished before, 1 to run"), sweeps.out());
        assertEquals(withoutWallTime(whole), withoutWallTime(results()));
    }
}
