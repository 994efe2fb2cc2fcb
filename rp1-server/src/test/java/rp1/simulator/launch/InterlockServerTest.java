package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;
import static rp1.testing.Await.letWallTimePass;

import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsHeartbeatEvent;
import rp1.simulator.Simulation;
import rp1.simulator.scheduler.Scheduler;

/**
 * The interlock through the real server at simulationSpeed=1000 (behavior.md section 4.5): the clock
 * waits for acknowledgements, and a client that vanishes releases what it held.
 */
@Timeout(30)
class InterlockServerTest {
    @TempDir
    Path dir;
    private RunningServer server;

    @BeforeEach
    void start() throws Exception {
        // Its clients use timeouts without placing a robot: time must run without waiting for one.
        server = TestServer.start(dir, "simulationSpeed=1000", "interlockEnabled=true", "waitForClients=0");
    }

    @AfterEach
    void stop() throws Exception {
        server.stop();
    }

    @Test
    void theClockStandsStillUntilTheNewestEventIsAcknowledged() throws Exception {
        try (RawClient c = RawClient.connected(server.getPort())) {
            c.sendBody();
            c.sendTimeout(0.5, 1);
            RawClient.Event first = c.awaitEvent(RawClient.EVT_TIMEOUT);
            assertTrue(first.interlock > 0, "the event opens the interlock");
            c.sendTimeout(0.0, 2);
            Simulation simulation = server.getSimulation();
            await(() -> !simulation.getInputs().isSettled(), Duration.ofSeconds(10),
                    "the server received the zero-length timeout request");
            assertFalse(simulation.getScheduler().isClockRunning(), "the interlock holds the clock");
            double frozen = simulation.getSimTime();
            simulation.pump();
            // A running paced clock reads the wall clock itself: whatever the load, it would have moved.
            letWallTimePass(Duration.ofMillis(300));
            assertEquals(frozen, simulation.getSimTime(), "no simulated time passes while the interlock is open");
            assertFalse(simulation.getInputs().isSettled(),
                    "no task runs while the interlock is open, not even a zero-length timeout: its request waits");
            assertEquals(0, c.in.available(), "no event was sent");
            c.sendInterlock(first.interlock - 1);
            c.sendInterlock(first.interlock);
            RawClient.Event second = c.readEvent();
            assertEquals(2, second.value);
            // The clock froze when the first event went out, a scheduling delay after its due time; the
            // 300 ms of waiting would have been 300 simulated seconds.
            double elapsed = second.simTime - first.simTime;
            assertTrue(elapsed >= 0.0 && elapsed < 30.0, "the wait cost no simulated time: " + elapsed);
            assertEquals(first.interlock + 1, second.interlock);
        }
    }

    @Test
    void aClientThatVanishesWithoutAcknowledgingReleasesTheClock() throws Exception {
        TcpRobot steady = TcpRobot.connect(server.getPort(), "steady").startLoop();
        steady.sendHeartbeatRequest(10.0);
        steady.await(RsHeartbeatEvent.class, e -> e.sequence >= 2);
        RawClient holder = RawClient.connected(server.getPort());
        holder.sendBody();
        holder.sendTimeout(0.0, 1);
        RawClient.Event held = holder.awaitEvent(RawClient.EVT_TIMEOUT);
        assertTrue(held.interlock > 0);
        Scheduler scheduler = server.getSimulation().getScheduler();
        assertFalse(scheduler.isClockRunning(), "the event to the silent client stopped the clock");
        double frozen = scheduler.now();
        // Meanwhile the steady client acknowledges what it was sent; that must not restart the clock.
        letWallTimePass(Duration.ofMillis(300));
        assertFalse(scheduler.isClockRunning(), "the clock waits for the silent client");
        assertEquals(frozen, scheduler.now(), "no simulated time passed while the silent client held the clock");
        int during = steady.events(RsHeartbeatEvent.class).size();
        holder.close();
        steady.await(RsHeartbeatEvent.class, e -> e.sequence >= during + 3);
        steady.leave();
    }
}
