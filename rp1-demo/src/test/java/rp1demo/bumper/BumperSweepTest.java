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
    private static final String HEADER =
            "seed,plan,robot,end_time,end_reason,exit_status,x,y,heading,distance,collisions,events,wall_seconds";

    @TempDir
    Path dir;

    private List<String> sweep(String seeds, String jobs, String out) throws Exception {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(text, true, StandardCharsets.UTF_8);
        int status = Sweep.run(new String[] {"-p", dir.resolve("bumper.ini").toString(), "--seeds", seeds,
            "--jobs", jobs, "--out", dir.resolve(out).toString()}, print, print, false);
        assertEquals(0, status, text.toString(StandardCharsets.UTF_8));
        return Files.readAllLines(dir.resolve(out).resolve("results.csv"));
    }

    /** A row without its last field, the wall-clock seconds. */
    private static String withoutWallTime(String row) {
        return row.substring(0, row.lastIndexOf(','));
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
            String[] f = rows.get(i).split(",");
            assertEquals(13, f.length, rows.get(i));
            assertEquals(Integer.toString(i), f[0], "seeds in order");
            assertEquals("contest.txt", f[1]);
            assertEquals("20.0", f[3]);
            assertEquals("max-simulation-time", f[4]);
            assertEquals("0", f[5]);
            assertTrue(Double.parseDouble(f[9]) > 0.5, "it drove: " + rows.get(i));
            assertTrue(Long.parseLong(f[11]) > 0, "it was sent events: " + rows.get(i));
            collisions += Integer.parseInt(f[10]);
            ends.add(f[6] + " " + f[7]);
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
