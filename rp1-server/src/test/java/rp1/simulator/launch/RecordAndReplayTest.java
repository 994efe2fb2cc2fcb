package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
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
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Runs recorded through the real server, replayed without their clients: the replay's event log is
 * the run's, byte for byte, and so is the picture where it ends.
 */
@Timeout(60)
class RecordAndReplayTest {
    private static final String[] RECORDING = {"recordFileName=run.rec", "eventLogFileName=run.events",
        "snapshotFileName=%s/run.png"};

    @TempDir
    Path dir;

    @Test
    void twoRobotsThatCollideAtMaxSpeedReplayToTheSameEventsAndPicture() throws Exception {
        RunningServer server = TestServer.start(dir, with("simulationSpeed=max", "interlockEnabled=true",
                "waitForClients=2", "robotsInteract=true"));
        TcpRobot driver = placed(server, "driver", 1);
        TcpRobot parked = placed(server, "parked", 2);
        driver.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 10.0));
        RsMotionHaltedEvent halt = driver.await(RsMotionHaltedEvent.class, e -> true);
        assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halt.causeOfHalt, "the driver ran into the parked robot");
        server.stop();
        driver.leave();
        parked.leave();

        assertReplayIsTheRun();
        assertTrue(text("run.events").contains(" MotionHalted causeOfHalt=2 "), "the log shows the collision");
    }

    @Test
    void aNetworkClientInAPacedRunWithViewInputsReplaysToTheSameEventsAndPicture() throws Exception {
        RunningServer server = TestServer.start(dir, with("simulationSpeed=8"));
        TcpRobot robot = TcpRobot.connectWithPen(server.getPort(), "paced");
        robot.addMouseClickEventHandler(e -> { });
        robot.penDown();
        robot.startLoop();
        robot.sendPlacementRequest(TestServer.placementName(1));
        robot.await(RsPlacementEvent.class, e -> e.valid);
        robot.sendHeartbeatRequest(0.25);
        robot.sendMotionRequest(new RsMotionRequest(0.4, 0.3, 2.0));
        server.getSimulation().mouseClick(1, 2, 5.0, 6.0);
        robot.await(RsMotionHaltedEvent.class, e -> true);
        server.getSimulation().removePaintTrails();
        robot.penDown();
        robot.sendMotionRequest(new RsMotionRequest(0.3, 0.0, 1.0));
        robot.await(RsMotionHaltedEvent.class, e -> e.simTime > 2.5);
        robot.await(RsHeartbeatEvent.class, e -> e.sequence >= 14);
        server.stop();
        robot.leave();

        assertReplayIsTheRun();
        String events = text("run.events");
        assertTrue(events.contains(" MouseClick button=1 clickCount=2 x=5.0 y=6.0"), "the click was replayed");
        assertTrue(events.contains(" Heartbeat sequence=14"), "heartbeats were replayed");
    }

    /**
     * The start-up warm-up (network clients enabled) must leave the real plan alone: random target
     * selection then draws from the seeded source, which the replay, having no warm-up, uses too.
     */
    @Test
    void randomTargetSelectionAfterTheWarmUpReplaysToTheSameEvents() throws Exception {
        StringBuilder plan = new StringBuilder("wall s { geometry: 0, 0, 10, 0, 0.05; }\n"
                + "wall n { geometry: 10, 10, 0, 10, 0.05; }\n"
                + "placement p1 { geometry: 2, 2, 0, 0.2; }\n");
        for (int i = 1; i <= 12; i++) {
            plan.append("target t").append(i).append(" { geometry: ").append(i * 0.7).append(", 8, 0.1; }\n");
        }
        Files.write(dir.resolve("targets.txt"), plan.toString().getBytes(StandardCharsets.UTF_8));
        RunningServer server = TestServer.start(dir, with("floorPlanFileName=targets.txt", "simulationSpeed=max",
                "interlockEnabled=true", "randomSeed=5"));
        TcpRobot robot = TcpRobot.connect(server.getPort(), "picker");
        robot.addTargetSelectionEventHandler(e -> { });
        robot.startLoop();
        robot.sendPlacementRequest("p1");
        robot.await(RsPlacementEvent.class, e -> e.valid);
        for (int i = 0; i < 8; i++) {
            robot.sendExclusiveRandomTargetSelectionRequest();
        }
        robot.sendTimeoutRequest(0.1);
        robot.await(RsTimeoutEvent.class, e -> true);
        server.stop();
        robot.leave();

        assertReplayIsTheRun();
        assertTrue(text("run.events").contains(" TargetSelection "), "the log shows the selections");
    }

    /** The server's lines plus the recording keys (the picture in the temporary directory). */
    private String[] with(String... lines) {
        String[] all = new String[lines.length + RECORDING.length];
        System.arraycopy(lines, 0, all, 0, lines.length);
        for (int i = 0; i < RECORDING.length; i++) {
            all[lines.length + i] = String.format(RECORDING[i], dir);
        }
        return all;
    }

    private static TcpRobot placed(RunningServer server, String name, int placement) throws Exception {
        TcpRobot robot = TcpRobot.connect(server.getPort(), name).startLoop();
        robot.sendPlacementRequest(TestServer.placementName(placement));
        robot.await(RsPlacementEvent.class, e -> e.valid);
        return robot;
    }

    /** A recording that is not there, or an output that cannot be written, is told as such, with the file. */
    @Test
    void aReplayThatCannotReadOrWriteSaysWhy() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream errors = new PrintStream(err, true, StandardCharsets.UTF_8);
        Path missing = dir.resolve("nosuch.rec");
        assertEquals(1, Replay.run(new String[] {missing.toString()}, System.out, errors));
        assertEquals("rp1.Replay: cannot read the recording " + missing + ": no such file or folder\n",
                err.toString(StandardCharsets.UTF_8));

        RunningServer server = TestServer.start(dir, with("simulationSpeed=max", "interlockEnabled=true"));
        TcpRobot robot = placed(server, "alone", 1);
        server.stop();
        robot.leave();
        err.reset();
        Path inTheWay = Files.writeString(dir.resolve("ro"), "a file, not a folder");
        Path picture = inTheWay.resolve("end.png");
        assertEquals(1, Replay.run(new String[] {dir.resolve("run.rec").toString(), "--snapshot", picture.toString()},
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8), errors));
        assertEquals("rp1.Replay: cannot write the picture " + picture + ": a file of that name is in the way\n",
                err.toString(StandardCharsets.UTF_8));
    }

    private void assertReplayIsTheRun() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {dir.resolve("run.rec").toString(), "--events",
            dir.resolve("replay.events").toString(), "--snapshot", dir.resolve("replay.png").toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, status, "replayed: " + out + err);
        assertTrue(out.toString(StandardCharsets.UTF_8).contains("the events are those of the recorded run"), out.toString());
        assertEquals(text("run.events"), text("replay.events"));
        assertArrayEquals(Files.readAllBytes(dir.resolve("run.png")), Files.readAllBytes(dir.resolve("replay.png")),
                "the replay's picture is the run's");
    }

    private String text(String file) throws IOException {
        return new String(Files.readAllBytes(dir.resolve(file)), StandardCharsets.UTF_8);
    }
}
