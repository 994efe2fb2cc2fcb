package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsPlacementEvent;

/**
 * A world waits for its robots: at {@code simulationSpeed=max} simulated time stands still while no
 * robot is on the floor, and {@code waitForClients=N} holds it at 0 until N robots are placed (by
 * default 1 when network clients are enabled and no client is loaded). Before, a max-speed server
 * with a time limit ran to the end before anybody had connected.
 */
@Timeout(60)
class WaitForClientsTest {
    @TempDir
    Path dir;

    @Test
    void aMaxSpeedServerWithATimeLimitWaitsForItsFirstRobot() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true",
                "maxSimulationTime=5");
        try {
            assertEquals(1, server.getConfig().waitForClients, "the default with network clients only");
            assertEquals(OptionalInt.empty(), server.awaitExit(300, TimeUnit.MILLISECONDS), "still waiting for a robot");
            TcpRobot robot = TcpRobot.connect(server.getPort(), "late").startLoop();
            robot.sendHeartbeatRequest(1.0);
            robot.sendPlacementRequest(TestServer.placementName(1));
            assertEquals(OptionalInt.of(ExitStatus.OK), server.awaitExit(20, TimeUnit.SECONDS));
            assertEquals(5, robot.events(RsHeartbeatEvent.class).size(), "beats 1 to 5, the last at the time limit");
        } finally {
            server.stop();
        }
    }

    @Test
    void waitForClientsHoldsTimeAtZeroUntilThatManyRobotsArePlaced() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=100", "waitForClients=2");
        try {
            TcpRobot first = TcpRobot.connect(server.getPort(), "first").startLoop();
            first.sendHeartbeatRequest(0.5);
            first.sendPlacementRequest(TestServer.placementName(1));
            first.await(RsPlacementEvent.class, e -> e.valid);
            Thread.sleep(300);
            assertTrue(first.events(RsHeartbeatEvent.class).isEmpty(), "30 simulated seconds would have passed");
            TcpRobot second = TcpRobot.connect(server.getPort(), "second").startLoop();
            second.sendPlacementRequest(TestServer.placementName(2));
            RsHeartbeatEvent beat = first.await(RsHeartbeatEvent.class, e -> true);
            assertEquals(0.5, beat.simTime, 1e-9, "time began when the second robot was placed");
            assertFalse(server.hasExited());
            first.leave();
            second.leave();
        } finally {
            server.stop();
        }
    }

    @Test
    void atMaxSpeedTimeStandsStillWhileNoRobotIsOnTheFloor() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true", "waitForClients=0");
        try {
            TcpRobot robot = TcpRobot.connect(server.getPort(), "unplaced").startLoop();
            robot.sendHeartbeatRequest(0.5);
            Thread.sleep(300);
            assertTrue(robot.events(RsHeartbeatEvent.class).isEmpty(), "no robot on the floor, no time passing");
            robot.sendPlacementRequest(TestServer.placementName(1));
            assertEquals(0.5, robot.await(RsHeartbeatEvent.class, e -> true).simTime, 1e-9);
            robot.leave();
        } finally {
            server.stop();
        }
    }
}
