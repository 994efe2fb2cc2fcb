package rp1demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * Three different loaded robots in one arena (Properties/headless.ini with three names in
 * {@code dlcName}): every run with the same seed, in one process one after the other, writes the same
 * event log and the same recording, byte for byte. Each client's {@code initialize()} runs on a thread
 * of its own; the server starts them in the listed order and numbers their parts per body.
 */
@Timeout(120)
class SeveralLoadedRobotsTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", ".."));
    private static final int RUNS = 10;

    @TempDir
    Path dir;

    @Test
    void threeLoadedRobotsGiveTheSameEventLogAndRecordingInEveryRun() throws Exception {
        String first = null;
        byte[] firstRecording = null;
        for (int run = 1; run <= RUNS; run++) {
            Path runDir = Files.createDirectories(dir.resolve("run" + run));
            String properties = new String(Files.readAllBytes(ROOT.resolve("Properties/headless.ini")), StandardCharsets.UTF_8)
                    + "\ndlcName=rp1demo.firefighter.FfMain,rp1demo.autopilot.ApMain,rp1demo.bumper.Bumper\n"
                    + "logToSystemOut=false\nlogToFile=true\nlogFileName=server.log\nmaxSimulationTime=30\n"
                    + "recordFileName=run.rec\neventLogFileName=run.events\nsnapshotFileName=" + dir.resolve("end.png") + "\n";
            Files.write(runDir.resolve("three.ini"), properties.getBytes(StandardCharsets.UTF_8));
            RunningServer server = ServerLauncher.start(new String[] {"-p", "three.ini"}, runDir, LaunchOptions.defaults());
            assertEquals(0, server.awaitExit(), "run " + run);
            String events = Files.readString(runDir.resolve("run.events"));
            byte[] recording = Files.readAllBytes(runDir.resolve("run.rec"));
            if (first == null) {
                first = events;
                firstRecording = recording;
                for (int client = 1; client <= 3; client++) {
                    assertTrue(events.contains("\n0.0 " + client + " Placement "), "robot " + client + " took part:\n" + events);
                }
                assertTrue(events.contains("\n0.0 1 Placement valid=true name=\"home\""),
                        "the fire fighter, listed first, is placed at home first:\n" + events);
            } else {
                assertSame(first, events, "event log of run " + run);
                assertSame(new String(firstRecording, StandardCharsets.UTF_8), new String(recording, StandardCharsets.UTF_8),
                        "recording of run " + run);
            }
        }
    }

    /** Fails with the first line where {@code actual} differs from {@code expected}. */
    private static void assertSame(String expected, String actual, String what) {
        String[] e = expected.split("\n", -1);
        String[] a = actual.split("\n", -1);
        for (int i = 0; i < Math.min(e.length, a.length); i++) {
            assertEquals(e[i], a[i], what + ", line " + (i + 1));
        }
        assertEquals(e.length, a.length, what + ": number of lines");
    }
}
