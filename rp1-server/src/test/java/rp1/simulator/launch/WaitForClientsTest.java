package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.simulator.Simulation;
import rp1.simulator.scheduler.Scheduler;

/**
 * A world waits for its robots: {@code waitForClients=N} holds simulated time at 0 until N robots are
 * placed, by default 1 at {@code simulationSpeed=max} with network clients and no loaded client (a
 * lockstep clock would otherwise run to its time limit before anybody connected) and 0 otherwise, so a
 * 0.60 client may ask for a timeout before it places a robot; and at {@code max} time stands still
 * while no robot is on the floor. A number that can never be met stops the server at start-up.
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
            assertEquals(1, server.getConfig().waitForClients, "the default at max with network clients only");
            TcpRobot robot = TcpRobot.connect(server.getPort(), "late").startLoop();
            robot.sendHeartbeatRequest(1.0);
            assertTimeStandsStillAtZero(server, 1.0);
            assertFalse(server.hasExited());
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
            assertTimeStandsStillAtZero(server, 0.5);
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
            assertTimeStandsStillAtZero(server, 0.5);
            robot.sendPlacementRequest(TestServer.placementName(1));
            assertEquals(0.5, robot.await(RsHeartbeatEvent.class, e -> true).simTime, 1e-9);
            robot.leave();
        } finally {
            server.stop();
        }
    }

    @Test
    void atAPacedSpeedABodilessClientAskingForATimeoutGetsItsAnswer() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=1");
        try (RawClient client = RawClient.connected(server.getPort())) {
            assertEquals(0, server.getConfig().waitForClients, "the default at a paced speed");
            client.sendTimeout(0.05, 7);
            RawClient.Event timeout = client.awaitEvent(RawClient.EVT_TIMEOUT);
            assertEquals(7, timeout.value);
            assertTrue(timeout.simTime >= 0.05, "at " + timeout.simTime);
        } finally {
            server.stop();
        }
    }

    @Test
    void aNumberOfRobotsThatCanNeverBePlacedIsAStartUpError() {
        StartupException none = assertThrows(StartupException.class, () -> TestServer.start(dir,
                "enableNetworkClients=false", "waitForClients=1"));
        assertEquals(ExitStatus.STARTUP_FAILED, none.getExitStatus());
        assertTrue(none.getMessage().contains("waitForClients=1 can never be met"), none.getMessage());
        assertTrue(none.getMessage().contains("enableNetworkClients=false"), none.getMessage());
        StartupException tooMany = assertThrows(StartupException.class, () -> TestServer.start(dir,
                "enableNetworkClients=false", "dlcEnabled=true", "dlcName=" + TestDlc.class.getName() + ","
                        + TestDlc.class.getName(), "waitForClients=3"));
        assertTrue(tooMany.getMessage().contains("waitForClients=3 can never be met")
                && tooMany.getMessage().contains("only 2 clients are loaded"), tooMany.getMessage());
    }

    /**
     * Waits until the server has taken in what was sent and can run nothing more with a task queued at
     * {@code nextTask}, and checks that simulated time is still 0: the clock is held, not merely slow.
     */
    private static void assertTimeStandsStillAtZero(RunningServer server, double nextTask) throws InterruptedException {
        Simulation simulation = server.getSimulation();
        Scheduler scheduler = simulation.getScheduler();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!(simulation.getInputs().isSettled() && scheduler.nextTaskTime() == nextTask && scheduler.isIdle())) {
            if (System.nanoTime() > deadline) {
                fail("the server did not settle with a task queued at " + nextTask + "; next task at "
                        + scheduler.nextTaskTime());
            }
            Thread.sleep(1);
        }
        assertEquals(0.0, simulation.getSimTime(), "time is held at 0 with a task queued at " + nextTask);
    }
}
