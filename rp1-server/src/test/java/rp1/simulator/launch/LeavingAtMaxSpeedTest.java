package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;

/**
 * At {@code simulationSpeed=max} with the interlock a client that leaves takes its robot away at the
 * first moment the clock would wait for it, however long its connection takes to go down; and a run
 * with a time limit that every client and robot has left ends at once, with a reason, instead of
 * standing still forever short of {@code maxSimulationTime}, as does one that nobody can join. Before,
 * the same client gave different event logs and the server never exited. The run, ended that way,
 * replays to the same events.
 */
@Timeout(120)
class LeavingAtMaxSpeedTest {
    /** Wall milliseconds between a client's last acknowledgement and the end of its connection, one run each. */
    private static final int[] CLOSE_DELAYS = {0, 2, 10, 40};

    @TempDir
    Path dir;

    @Test
    void aClientLeavingAtAFixedSimulatedTimeGivesTheSameEventLogWhateverTheTimingAndTheRunEnds() throws Exception {
        String first = null;
        for (int delay : CLOSE_DELAYS) {
            String log = runOnce(dir.resolve("run-" + delay), delay);
            if (first == null) {
                first = log;
                assertTrue(first.contains("\n2.25 1 Heartbeat sequence=9") && !first.contains("\n2.5 1 "),
                        "the robot left when the clock would next wait for its client, at its beat at 2.25 s:\n"
                                + first);
            } else {
                assertEquals(first, log, "the event log of a run whose client closed " + delay
                        + " ms after its last acknowledgement");
            }
        }
        assertReplaysToTheSameEvents(dir.resolve("run-" + CLOSE_DELAYS[CLOSE_DELAYS.length - 1]));
    }

    private static void assertReplaysToTheSameEvents(Path run) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {run.resolve("run.rec").toString(), "--events",
            run.resolve("replay.txt").toString()}, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(out, true, StandardCharsets.UTF_8));
        assertEquals(0, status, out.toString(StandardCharsets.UTF_8));
        assertEquals(Files.readString(run.resolve("events.txt")), Files.readString(run.resolve("replay.txt")));
    }

    @Test
    void aMaxSpeedRunWithoutNetworkClientsEndsWhenItsLoadedClientHasLeft() throws Exception {
        TestDlc.reset();
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true",
                "enableNetworkClients=false", "dlcEnabled=true", "dlcName=" + TestDlc.class.getName(),
                "dlcDelivery=pipes");
        try {
            assertEquals(OptionalInt.of(ExitStatus.OK), server.awaitExit(20, TimeUnit.SECONDS),
                    "nobody can come: the run ends instead of standing still");
            assertEquals(RunningServer.NOBODY_LEFT, server.getStopReason());
            assertTrue(TestServer.log(dir).contains("network clients are disabled, so nothing more can happen"),
                    TestServer.log(dir));
            assertEquals(5, TestDlc.BEATS.size());
        } finally {
            server.stop();
        }
    }

    /** A max-speed run that no client can ever join ends at once: it used to stand at time 0 for ever. */
    @Test
    void aMaxSpeedRunThatNoClientCanJoinEndsAtOnce() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true",
                "enableNetworkClients=false", "dlcEnabled=false", "maxSimulationTime=1");
        try {
            assertEquals(OptionalInt.of(ExitStatus.OK), server.awaitExit(20, TimeUnit.SECONDS), "it ends by itself");
            assertEquals(RunningServer.NOBODY_LEFT, server.getStopReason());
            assertTrue(TestServer.log(dir).contains("No client is loaded and network clients are disabled"),
                    TestServer.log(dir));
        } finally {
            server.stop();
        }
    }

    /** One run: the client acknowledges the beat at 2.0 s, waits {@code delay} ms, closes; the event log. */
    private static String runOnce(Path dir, int delay) throws Exception {
        Files.createDirectories(dir);
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true",
                "maxSimulationTime=10", "eventLogFileName=events.txt", "recordFileName=run.rec", "randomSeed=1");
        try {
            try (RawClient c = RawClient.connected(server.getPort())) {
                c.sendBody();
                c.sendHeartbeat(0.25);
                c.sendPlacement(TestServer.placementName(1));
                RawClient.Event beat;
                do {
                    beat = c.awaitEvent(RawClient.EVT_HEARTBEAT);
                    c.sendInterlock(beat.interlock);
                } while (beat.simTime < 2.0);
                Thread.sleep(delay);
            }
            assertEquals(OptionalInt.of(ExitStatus.OK), server.awaitExit(20, TimeUnit.SECONDS),
                    "the server ends although maxSimulationTime can never come");
            assertEquals(RunningServer.NOBODY_LEFT, server.getStopReason());
            assertTrue(TestServer.log(dir).contains("No robot is left and no client is connected"),
                    TestServer.log(dir));
            return new String(Files.readAllBytes(dir.resolve("events.txt")), StandardCharsets.UTF_8);
        } finally {
            server.stop();
        }
    }
}
