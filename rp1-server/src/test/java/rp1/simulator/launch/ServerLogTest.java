package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The server log's line format (behavior.md section 3.9) and its targets. */
class ServerLogTest {

    @Test
    void linesCarryLevelTwelveHourWallClockAndSimulationTimeModulo10000() {
        assertEquals("s 4:26:29.386 0000.000: modelingFrameInterval (sec): 0.1",
                ServerLog.format("s", LocalTime.of(16, 26, 29, 386_000_000), 0.0, "modelingFrameInterval (sec): 0.1"));
        assertEquals("X 12:05:00.007 0012.345: m", ServerLog.format("X", LocalTime.of(0, 5, 0, 7_000_000), 12.345, "m"));
        assertEquals("v 1:00:00.000 0002.999: m", ServerLog.format("v", LocalTime.of(13, 0), 10002.9999, "m"));
    }

    @Test
    void theWallClockReadsAsTheTwelveHourPatternWouldWriteIt() {
        DateTimeFormatter pattern = DateTimeFormatter.ofPattern("h:mm:ss.SSS", Locale.ROOT);
        // Every hour, minute and second boundary of a day and the milliseconds between, in steps that
        // visit each digit position.
        for (long millis = 0; millis < 86_400_000L; millis += 997) {
            LocalTime t = LocalTime.ofNanoOfDay(millis * 1_000_000L + 123_456L);
            assertEquals(pattern.format(t), ServerLog.clock(new StringBuilder(), t).toString());
        }
        assertEquals("12:00:00.000", ServerLog.clock(new StringBuilder(), LocalTime.MIDNIGHT).toString());
        assertEquals("12:00:00.000", ServerLog.clock(new StringBuilder(), LocalTime.NOON).toString());
        assertEquals("11:59:59.999", ServerLog.clock(new StringBuilder(), LocalTime.MAX).toString());
    }

    @Test
    void verboseLinesAreWrittenOnlyWhenVerboseAndEveryLineIsFlushedAtOnce(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("quiet.log");
        ServerLog log = ServerLog.open(file.toString(), false, false);
        log.setSimTime(() -> 1.5);
        log.log("standard");
        log.verbose("chatter");
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        assertEquals(1, lines.size(), "flushed before close: " + lines);
        assertTrue(lines.get(0).matches("s \\d{1,2}:\\d\\d:\\d\\d\\.\\d{3} 0001\\.500: standard"), lines.get(0));
        log.setVerbosity(true);
        log.verbose("chatter");
        log.close();
        log.log("after close");
        String all = new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
        assertTrue(all.contains("v "));
        assertFalse(all.contains("after close"));
    }
}
