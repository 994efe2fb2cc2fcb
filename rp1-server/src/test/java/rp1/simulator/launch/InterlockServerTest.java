package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.SocketTimeoutException;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsHeartbeatEvent;

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
            c.socket.setSoTimeout(300);
            assertThrows(SocketTimeoutException.class, c::readEvent,
                    "no task runs while the interlock is open, not even a zero-length timeout");
            c.socket.setSoTimeout(10_000);
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
        int before = steady.events(RsHeartbeatEvent.class).size();
        Thread.sleep(300);
        int during = steady.events(RsHeartbeatEvent.class).size();
        assertTrue(during <= before + 1, "the clock waits for the silent client: " + before + " then " + during);
        holder.close();
        steady.await(RsHeartbeatEvent.class, e -> e.sequence >= during + 3);
        steady.leave();
    }
}
