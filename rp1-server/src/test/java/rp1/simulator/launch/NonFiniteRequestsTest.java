package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsTimeoutEvent;
import rp1.simulator.world.Robot;

/**
 * Issue 18.3 over a real listener: a client sending NaN in a request is dropped with a log line naming
 * the field, and the paced server goes on serving the others, its clock advancing. (One NaN timeout
 * used to wedge the task thread for good; a NaN turn rate gave a robot a NaN pose.)
 */
@Timeout(60)
class NonFiniteRequestsTest {
    private static final String DROPPED = ": RsConnection terminating due to exception on input: ";

    @TempDir
    Path dir;

    private static String who(RawClient c) {
        return "(/127.0.0.1:" + c.socket.getLocalPort() + ")";
    }

    @Test
    void aNaNTimeoutDropsItsSenderAndThePacedServerServesTheOthersOnTime() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=10", "waitForClients=0");
        try {
            TcpRobot good = TcpRobot.connect(server.getPort(), "good").startLoop();
            try (RawClient nan = RawClient.connected(server.getPort())) {
                nan.sendBody();
                nan.sendTimeout(Double.NaN, 1);
                TestServer.awaitLog(dir, who(nan) + DROPPED + "timeout duration: NaN is not a finite number");
                TestServer.awaitLog(dir, who(nan) + " disconnected");
            }
            good.sendTimeoutRequest(0.5);
            RsTimeoutEvent first = good.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 1);
            good.sendTimeoutRequest(0.5);
            RsTimeoutEvent second = good.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 2);
            assertTrue(first.simTime >= 0.5, "time advanced: " + first.simTime);
            assertTrue(second.simTime >= first.simTime + 0.5, first.simTime + " then " + second.simTime);
            good.leave();
        } finally {
            server.stop();
        }
    }

    private static void assertTheRobotsLeave(RunningServer server) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        List<Robot> robots = server.getSimulation().getWorld().getRobots();
        while (!robots.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(10);
            robots = server.getSimulation().getWorld().getRobots();
        }
        assertEquals(0, robots.size(), "the dropped clients' robots have left: " + robots);
    }

    @Test
    void aMotionWithANonFiniteTurnRateDropsItsSenderBeforeAnyRobotMoves() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=10", "waitForClients=0");
        try {
            try (RawClient nan = RawClient.connected(server.getPort());
                 RawClient infinite = RawClient.connected(server.getPort())) {
                nan.sendBody();
                nan.sendPlacement(TestServer.placementName(0));
                nan.sendMotion(0.5, Double.NaN, 2.0);
                infinite.sendBody();
                infinite.sendHeartbeat(Double.NEGATIVE_INFINITY);
                TestServer.awaitLog(dir, who(nan) + DROPPED + "motion rotational velocity: NaN is not a finite number");
                TestServer.awaitLog(dir, who(infinite) + DROPPED + "heartbeat interval: -Infinity is not a finite number");
                TestServer.awaitLog(dir, who(nan) + " disconnected");
                TestServer.awaitLog(dir, who(infinite) + " disconnected");
            }
            assertTheRobotsLeave(server);
            try (RawClient late = RawClient.connected(server.getPort())) {
                late.sendTimeout(0.2, 1);
                assertEquals(1, late.awaitEvent(RawClient.EVT_TIMEOUT).value, "the server still serves");
            }
        } finally {
            server.stop();
        }
    }
}
