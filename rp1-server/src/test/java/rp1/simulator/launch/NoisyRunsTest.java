package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Noisy runs through the real server: the noise keys switch it on, one seed gives one event log,
 * another seed another, and a recording of a noisy run replays to its events.
 */
@Timeout(60)
class NoisyRunsTest {
    private static final int MOTIONS = 8;

    @TempDir
    Path dir;

    @Test
    void oneSeedGivesOneEventLogAndAnotherSeedAnother() throws Exception {
        String first = run("first", 21L, "noiseSlipDistanceSigma=0.1", "noiseSlipTurnSigma=0.1");
        String again = run("again", 21L, "noiseSlipDistanceSigma=0.1", "noiseSlipTurnSigma=0.1");
        String other = run("other", 22L, "noiseSlipDistanceSigma=0.1", "noiseSlipTurnSigma=0.1");
        assertEquals(first, again);
        assertNotEquals(first, other);
        assertEquals(run("plain", 21L), run("plain2", 22L), "without noise the seed does not matter here");
    }

    @Test
    void zeroNoiseKeysGiveTheEventLogOfNone() throws Exception {
        assertEquals(run("plain", 21L), run("zero", 21L, "noiseRangeSigma=0", "noiseRangeDropout=0",
                "noiseTargetRangeSigma=0", "noiseTargetBearingSigma=0", "noiseEncoderMiss=0",
                "noiseSlipDistanceSigma=0", "noiseSlipTurnSigma=0"));
    }

    @Test
    void aNoisyRunReplaysToItsEvents() throws Exception {
        String events = run("noisy", 23L, "noiseSlipDistanceSigma=0.1", "noiseSlipTurnSigma=0.2");
        Path run = dir.resolve("noisy");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {run.resolve("run.rec").toString(), "--events",
            run.resolve("replay.events").toString()}, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(out, true, StandardCharsets.UTF_8));
        assertEquals(0, status, "replayed: " + out);
        assertEquals(events, text(run.resolve("replay.events")));
    }

    /**
     * A robot at the arena's first placement that drives and turns {@link #MOTIONS} times and asks
     * where it is after each (the truth, which slip moves), at max speed with a recording and an
     * event log in {@code name}; the event log.
     */
    private String run(String name, long seed, String... noise) throws Exception {
        Path folder = Files.createDirectories(dir.resolve(name));
        String[] lines = {"simulationSpeed=max", "interlockEnabled=true", "randomSeed=" + seed,
            "recordFileName=run.rec", "eventLogFileName=run.events"};
        String[] all = new String[lines.length + noise.length];
        System.arraycopy(lines, 0, all, 0, lines.length);
        System.arraycopy(noise, 0, all, lines.length, noise.length);
        RunningServer server = TestServer.start(folder, all);
        TcpRobot robot = TcpRobot.connect(server.getPort(), "wanderer");
        int[] halts = {0};
        robot.addMotionHaltedEventHandler(e -> {
            robot.sendPositionRequest();
            if (++halts[0] < MOTIONS) {
                robot.sendMotionRequest(new RsMotionRequest(0.5, halts[0] % 2 == 0 ? 0.0 : 1.2, 1.0));
            } else {
                robot.sendTimeoutRequest(0.5);
            }
        });
        robot.startLoop();
        robot.sendPlacementRequest(TestServer.placementName(1));
        robot.await(RsPlacementEvent.class, e -> e.valid);
        robot.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 1.0));
        robot.await(RsTimeoutEvent.class, e -> true);
        server.stop();
        robot.leave();
        String events = text(folder.resolve("run.events"));
        assertTrue(events.split("\n").length > MOTIONS, events);
        return events;
    }

    private static String text(Path file) throws IOException {
        return new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
    }
}
