package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.nio.file.Path;
import java.time.Duration;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Loaded clients that keep the library's event loop get their events by direct calls on the thread
 * running the simulation ({@code dlcDelivery=auto} or {@code direct}); others, or any with
 * {@code dlcDelivery=pipes}, go through pipes.
 */
@Timeout(60)
class DirectDeliveryTest {
    private static final String CLIENT = "dlcName=" + DirectDlc.class.getName();

    @TempDir
    Path dir;

    private int runToTheEnd(String... lines) throws Exception {
        RunningServer server = TestServer.start(dir, lines);
        OptionalInt status = server.awaitExit(20, TimeUnit.SECONDS);
        if (!status.isPresent()) {
            server.stop();
            throw new AssertionError("the server did not stop by itself:\n" + TestServer.log(dir));
        }
        return status.getAsInt();
    }

    @Test
    void aClientWithTheStandardEventLoopIsCalledDirectlyAndIsDoneWhenItsSessionEnds() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", CLIENT, "exitWhenClientsDone=true", "simulationSpeed=max",
                "interlockEnabled=true", "enableNetworkClients=false");
        assertEquals(ExitStatus.OK, status, TestServer.log(dir));
        String log = TestServer.log(dir);
        assertTrue(log.contains("client 1 (in-process " + DirectDlc.class.getName() + ", direct) connected"), log);
        DirectDlc c = DirectDlc.latest;
        assertEquals(10, c.beatThreads.size());
        assertFalse(c.beatThreads.stream().anyMatch(t -> t.startsWith("dlc ")), "no thread of the client's own: "
                + c.beatThreads);
    }

    @Test
    void dlcDeliveryPipesKeepsEvenSuchAClientOnPipes() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", CLIENT, "exitWhenClientsDone=true", "simulationSpeed=max",
                "interlockEnabled=true", "enableNetworkClients=false", "dlcDelivery=pipes");
        assertEquals(ExitStatus.OK, status, TestServer.log(dir));
        assertTrue(TestServer.log(dir).contains("client 1 (in-process " + DirectDlc.class.getName() + ") connected"));
        assertTrue(DirectDlc.latest.beatThreads.stream().allMatch(t -> t.startsWith("dlc ")),
                "the client's own event loop: " + DirectDlc.latest.beatThreads);
    }

    @Test
    void dlcDeliveryDirectForAClientWithItsOwnLoopStopsTheStartWithTheReason() {
        StartupException e = assertThrows(StartupException.class, () -> TestServer.start(dir, "dlcEnabled=true",
                "dlcName=" + TestDlc.class.getName(), "dlcDelivery=direct"));
        assertEquals("dlcDelivery=direct, but client class " + TestDlc.class.getName() + " cannot be called directly: "
                + "it overrides run() (in " + TestDlc.class.getName() + ") (use dlcDelivery=auto or pipes)", e.getMessage());
        assertEquals(ExitStatus.STARTUP_FAILED, e.getExitStatus());
    }

    @Test
    void requestsFromAnotherThreadAreSafeAndAppliedAtTheNextBoundary() throws Exception {
        DirectDlc.latest = null;
        RunningServer server = TestServer.start(dir, "dlcEnabled=true", CLIENT, "simulationSpeed=20",
                "enableNetworkClients=false");
        try {
            await(() -> DirectDlc.latest != null && DirectDlc.latest.beatThreads.size() >= 2, Duration.ofSeconds(30),
                    "the loaded client received two heartbeats");
            DirectDlc c = DirectDlc.latest;
            for (int i = 0; i < 100; i++) {
                c.sendPositionRequest();
            }
            await(() -> c.positions.size() >= 100, Duration.ofSeconds(30), "every request sent from this thread was answered");
            assertEquals(100, c.positions.size(), "every request sent from this thread was answered once");
            assertEquals(TestServer.placementX(1), c.positions.get(99).x, 1e-9);
        } finally {
            server.stop();
        }
    }
}
