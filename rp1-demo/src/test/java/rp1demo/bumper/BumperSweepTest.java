package rp1demo.bumper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;
import rp1.Sweep;

/**
 * The bumper car of Properties/bumper.ini swept over four seeds, two runs at a time: a row per run,
 * different seeds sending it different ways, every run replayable, and a seed run alone giving the
 * row it had in the batch.
 */
@Timeout(120)
class BumperSweepTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", ".."));
    private static final String HEADER = "seed,plan,run,robot,start_x,start_y,start_heading,end_x,end_y,end_heading,"
            + "end_time,distance,collisions,first_collision_time,events,status,reason,wall_seconds";

    @TempDir
    Path dir;

    private List<String> sweep(String seeds, String jobs, String out) throws Exception {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(text, true, StandardCharsets.UTF_8);
        int status = Sweep.run(new String[] {"-p", dir.resolve("bumper.ini").toString(), "--seeds", seeds,
            "--jobs", jobs, "--pictures", "--out", dir.resolve(out).toString()}, print, print, false);
        assertEquals(0, status, text.toString(StandardCharsets.UTF_8));
        // Its main method (run on its own over the network) ends the process, which a sweep's run never calls.
        assertTrue(!text.toString(StandardCharsets.UTF_8).contains("each run went in a process of its own"),
                text.toString(StandardCharsets.UTF_8));
        return Files.readAllLines(dir.resolve(out).resolve("results.csv"));
    }

    /** A row without its last field, the wall-clock seconds. */
    private static String withoutWallTime(String row) {
        return row.substring(0, row.lastIndexOf(','));
    }

    /** The distance of a run: the robot's path from start to end is at least as long as the straight line. */
    private static double straight(String[] f) {
        return Math.hypot(Double.parseDouble(f[7]) - Double.parseDouble(f[4]), Double.parseDouble(f[8]) - Double.parseDouble(f[5]));
    }

    @Test
    void fourSeedsInTwoJobsGiveARowEachAndASeedAloneGivesItsRowAgain() throws Exception {
        String properties = Files.readString(ROOT.resolve("Properties/bumper.ini")) + "\nmaxSimulationTime=20\n";
        Files.write(dir.resolve("bumper.ini"), properties.getBytes(StandardCharsets.UTF_8));

        List<String> rows = sweep("1-4", "2", "batch");
        assertEquals(HEADER, rows.get(0));
        assertEquals(5, rows.size(), rows.toString());
        Set<String> ends = new HashSet<>();
        int collisions = 0;
        for (int i = 1; i <= 4; i++) {
            String[] f = rows.get(i).split(",", -1);
            assertEquals(18, f.length, rows.get(i));
            assertEquals(Integer.toString(i), f[0], "seeds in order");
            assertEquals("contest.txt", f[1]);
            assertEquals("runs/" + i + "-contest", f[2]);
            assertEquals("Bumper", f[3], "the robot is named after its body");
            assertEquals("20", f[10]);
            assertEquals("0", f[15]);
            assertEquals("max-simulation-time", f[16]);
            assertTrue(Double.parseDouble(f[11]) > 0.5, "it drove: " + rows.get(i));
            assertTrue(Double.parseDouble(f[11]) >= straight(f) - 1e-3, "it went at least from start to end: " + rows.get(i));
            assertTrue(Long.parseLong(f[14]) > 0, "it was sent events: " + rows.get(i));
            int bumps = Integer.parseInt(f[12]);
            assertEquals(bumps == 0, f[13].isEmpty(), "the first collision's time is there when it collided: " + rows.get(i));
            collisions += bumps;
            ends.add(f[7] + " " + f[8]);
        }
        assertTrue(collisions > 0, "it bumped into walls: " + rows);
        assertEquals(4, ends.size(), "each seed put it somewhere else: " + rows);

        Path run = dir.resolve("batch/runs/3-contest");
        assertTrue(Files.size(run.resolve("end.png")) > 0);
        PrintStream quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertEquals(0, Replay.run(new String[] {run.resolve("recording.txt").toString(), "--events",
            dir.resolve("replayed.txt").toString()}, quiet, quiet));
        assertEquals(Files.readString(run.resolve("events.txt")), Files.readString(dir.resolve("replayed.txt")),
                "a row's run replays to its events");

        List<String> alone = sweep("3", "1", "alone");
        assertEquals(withoutWallTime(rows.get(3)), withoutWallTime(alone.get(1)));
    }
}
