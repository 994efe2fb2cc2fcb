package rp1.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * A crowd of the scale arena's wanderers, packed tighter than the benchmark's, gives the event log it
 * gave when this test was written, byte for byte. Robots meeting robots is where a crowd's time goes
 * and where its speed work happens (the contact search, sensing other robots, the robot index); this
 * log pins down what that work must leave as it is: every stop, every bumper and range reading, every
 * heartbeat, at its time. If a change to the model is meant, the new log is left in the build folder
 * ({@code build/scale-arena-transcript.txt}) to compare, and the digest here is updated with a reason.
 */
@Timeout(120)
class ScaleArenaTranscriptTest {
    private static final int ROBOTS = 200;
    /** 200 robots in 12 m: 1.4 a square metre, more than twice the density of 1,000 in 40 m. */
    private static final double ARENA = 12.0;
    private static final double SECONDS = 20.0;
    /** SHA-256 of the event log, as 0a9caaf wrote it. */
    private static final String DIGEST = "f5f4f34792ae2c26d91631fb24e4e426c494b41b400b70dcf43e9e976075dbe1";

    @Test
    void aCrowdOfWanderersGivesTheRecordedEventLog(@TempDir Path dir) throws Exception {
        Files.write(dir.resolve("arena.txt"), ScaleArena.plan(ARENA, ROBOTS).getBytes(StandardCharsets.UTF_8));
        List<String> names = new ArrayList<>();
        for (int i = 0; i < ROBOTS; i++) {
            names.add(ScaleWanderer.class.getName());
        }
        List<String> properties = List.of("floorPlanFileName=arena.txt", "enableGUI=false", "enableNetworkClients=false",
                "interlockEnabled=true", "simulationSpeed=max", "randomSeed=1", "maxSimulationTime=" + SECONDS,
                "dlcEnabled=true", "dlcName=" + String.join(",", names), "eventLogFileName=events.txt");
        Files.write(dir.resolve("run.ini"), String.join("\n", properties).getBytes(StandardCharsets.UTF_8));
        ScaleWanderer.startAnew();
        RunningServer server = ServerLauncher.start(new String[] {"-p", "run.ini"}, dir, LaunchOptions.defaults());
        if (server.awaitExit(100, TimeUnit.SECONDS).isEmpty()) {
            server.stop();
            throw new AssertionError("the crowd's run did not end in 100 s");
        }
        byte[] log = Files.readAllBytes(dir.resolve("events.txt"));
        String text = new String(log, StandardCharsets.UTF_8);
        assertEquals(ROBOTS, ScaleWanderer.PLACED.get(), "every wanderer placed");
        int collisions = count(text, "MotionHalted causeOfHalt=" + RsMotionHaltedEvent.HALTED_ON_COLLISION);
        assertTrue(collisions > 1000, "robots ran into each other many times, not " + collisions);
        String digest = HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(log));
        if (!digest.equals(DIGEST)) {
            Path kept = Path.of("build", "scale-arena-transcript.txt");
            Files.createDirectories(kept.getParent());
            Files.write(kept, log);
            assertEquals(DIGEST, digest, "the crowd's event log changed; it is in " + kept.toAbsolutePath());
        }
    }

    private static int count(String text, String word) {
        int n = 0;
        for (int i = text.indexOf(word); i >= 0; i = text.indexOf(word, i + 1)) {
            n++;
        }
        return n;
    }
}
