package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Paths;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** What the user sees while a sweep runs: a bar redrawn in place on a terminal, a line per run elsewhere. */
class ProgressTest {
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);

    private static Batch.Outcome outcome(long seed, RunReport report) {
        return new Batch.Outcome(new Batch.Run(Map.of(), seed, "contest.txt", Paths.get("runs", seed + "-contest")), report, 1.25,
                List.of());
    }

    @Test
    void onATerminalOneLineIsRedrawnWithTheBarTheRunsDoneAndFailedAndTheTimeLeft() {
        Progress p = new Progress(4, out, true);
        p.finished(outcome(1, new RunReport(10.0, "max-simulation-time", 0, List.of())));
        p.finished(outcome(2, RunReport.failed("client failed: boom", 2)));
        p.close();
        String text = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(text.startsWith("\r[#######.......................] 1/4 runs, 0 failed, about "), text);
        assertTrue(text.contains("\r[###############...............] 2/4 runs, 1 failed, about "), text);
        assertTrue(text.endsWith(" left   \n"), text);
    }

    @Test
    void elsewhereEachRunGetsALineSayingHowItEnded() {
        Progress p = new Progress(2, out, false);
        p.finished(outcome(7, RunReport.failed("timeout: still running after 600 s of wall time", 137)));
        p.close();
        assertEquals("[1/2] seed 7 on contest.txt: timeout: still running after 600 s of wall time (1.3 s)\n",
                bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    void wallTimeIsShownInMillisecondsBelowASecondAndInTenthsAbove() {
        assertEquals("0 ms", Progress.elapsed(0.0));
        assertEquals("4 ms", Progress.elapsed(0.0042));
        assertEquals("49 ms", Progress.elapsed(0.049));
        assertEquals("198 ms", Progress.elapsed(0.198));
        assertEquals("1.0 s", Progress.elapsed(0.9996));
        assertEquals("1.3 s", Progress.elapsed(1.25));
        assertEquals("10.0 s", Progress.elapsed(9.96));
        assertEquals("601.5 s", Progress.elapsed(601.47));
    }
}
