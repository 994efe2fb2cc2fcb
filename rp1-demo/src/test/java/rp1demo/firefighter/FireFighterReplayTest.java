package rp1demo.firefighter;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * The headless fire fighter (Properties/headless.ini) recorded by the server and replayed without it:
 * the same events, byte for byte, and the same picture of the arena at the end.
 */
@Timeout(60)
class FireFighterReplayTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", ".."));

    @TempDir
    Path dir;

    @Test
    void theFireFightersRunReplaysToTheSameEventLogAndEndPicture() throws Exception {
        String properties = new String(Files.readAllBytes(ROOT.resolve("Properties/headless.ini")), StandardCharsets.UTF_8)
                + "\nlogToSystemOut=false\nlogToFile=true\nlogFileName=ff.log\nmaxSimulationTime=30\n"
                + "recordFileName=ff.rec\neventLogFileName=ff.events\n"
                + "snapshotFileName=" + dir.resolve("ff.png") + "\n";
        Files.write(dir.resolve("ff.ini"), properties.getBytes(StandardCharsets.UTF_8));
        RunningServer server = ServerLauncher.start(new String[] {"-p", "ff.ini"}, dir, LaunchOptions.defaults());
        assertEquals(0, server.awaitExit());

        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {dir.resolve("ff.rec").toString(), "--events",
            dir.resolve("replay.events").toString(), "--snapshot", dir.resolve("replay.png").toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(out, true, StandardCharsets.UTF_8));
        assertEquals(0, status, out.toString(StandardCharsets.UTF_8));

        String run = Files.readString(dir.resolve("ff.events"));
        assertTrue(run.contains(" TargetSensor sensorID=") && run.contains("nameOfObjectDetected=\"C1\""),
                "the run saw the candle:\n" + run);
        assertEquals(run, Files.readString(dir.resolve("replay.events")));
        assertArrayEquals(Files.readAllBytes(dir.resolve("ff.png")), Files.readAllBytes(dir.resolve("replay.png")),
                "the replay's picture is the run's");
    }
}
