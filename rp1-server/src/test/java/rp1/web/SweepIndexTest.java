package rp1.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep's index.html, from the sweep's files alone: the summary, every run of results.csv, and
 * each run's replay page, written when asked for.
 */
@Timeout(120)
class SweepIndexTest {
    static final String RESULTS = "seed,plan,robot,end_time,end_reason,exit_status,distance,first_collision_time\n"
            + "1,WhiteRoom.txt,Wanderer,20.0,max-simulation-time,0,2.5,\n"
            + "2,WhiteRoom.txt,Wanderer,3.5,\"client failed: boom, \"\"twice\"\"\",2,0.25,1.5\n";

    /** A sweep's folder: results.csv and, for seed 1, a run folder with a recording. */
    static Path sweep(Path dir) throws Exception {
        Path run = Files.createDirectories(dir.resolve("runs/1-WhiteRoom"));
        Runs.record(run, 20.0);
        Files.move(run.resolve("run.rec"), run.resolve("recording.txt"));
        Files.write(dir.resolve("results.csv"), RESULTS.getBytes(StandardCharsets.UTF_8));
        return dir;
    }

    @Test
    void csvFieldsInQuotesKeepTheirCommasQuotesAndLineBreaks() {
        assertEquals(List.of(List.of("a", "b, \"c\"", "x\ny", ""), List.of("1", "2")),
                CsvTable.parse("a,\"b, \"\"c\"\"\",\"x\ny\",\r\n1,2\n"));
    }

    @Test
    void theIndexListsEveryRunAndLinksTheReplayPagesItWrote(@TempDir Path dir) throws Exception {
        sweep(dir);
        assertEquals(List.of(), SweepIndex.write(dir, true));
        Path page = dir.resolve("runs/1-WhiteRoom/replay.html");
        assertTrue(Files.exists(page), "the run's page was written");
        assertTrue(Files.readString(page).contains("\"name\":\"Wanderer\""));
        String index = Files.readString(dir.resolve("index.html"));
        assertTrue(index.contains("\"client failed: boom, \\\"twice\\\"\""), "the failed run's reason, whole");
        assertTrue(index.contains("\"folder\":\"runs/1-WhiteRoom\",\"page\":1"), "seed 1 links its page");
        assertTrue(index.contains("\"folder\":null,\"page\":0"), "seed 2 has no run folder");
        assertTrue(index.contains("[\"WhiteRoom.txt\",\"2\",\"1\"]"), "the summary per plan: 2 runs, 1 failed");
    }

    @Test
    void withoutPagesTheIndexSaysHowToWriteOneAndASummaryCsvIsShownAsItIs(@TempDir Path dir) throws Exception {
        sweep(dir);
        Files.write(dir.resolve("summary.csv"), "configuration,runs,mean_distance\nbumper,2,1.375\n".getBytes(StandardCharsets.UTF_8));
        SweepIndex.write(dir, false);
        assertFalse(Files.exists(dir.resolve("runs/1-WhiteRoom/replay.html")), "no page unless asked for");
        String index = Files.readString(dir.resolve("index.html"));
        assertTrue(index.contains("\"folder\":\"runs/1-WhiteRoom\",\"page\":0"), index);
        assertTrue(index.contains("[\"configuration\",\"runs\",\"mean_distance\"]") && index.contains("[\"bumper\",\"2\",\"1.375\"]"),
                "summary.csv as it is");
    }
}
