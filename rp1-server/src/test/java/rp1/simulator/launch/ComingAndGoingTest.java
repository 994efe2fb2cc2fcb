package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Clients that come, take the same placement and leave at once without acknowledging anything: a
 * robot whose client has gone leaves the world before any request that reached the server after it,
 * so every newcomer finds the placement free (RP1 0.60, and this server before, sometimes still had
 * the previous robot standing there).
 */
@Timeout(60)
class ComingAndGoingTest {
    private static final int CLIENTS = 300;

    @TempDir
    Path dir;

    @Test
    void threeHundredClientsInARowAllGetTheSamePlacementWithTheInterlock() throws Exception {
        assertAllPlaced(TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true"));
    }

    @Test
    void threeHundredClientsInARowAllGetTheSamePlacementWithoutTheInterlock() throws Exception {
        assertAllPlaced(TestServer.start(dir, "simulationSpeed=1", "interlockEnabled=false"));
    }

    private static void assertAllPlaced(RunningServer server) throws Exception {
        try {
            int refused = 0;
            for (int i = 0; i < CLIENTS; i++) {
                try (RawClient c = RawClient.connected(server.getPort())) {
                    c.sendBody();
                    c.sendPlacement(TestServer.placementName(1));
                    if (c.awaitEvent(RawClient.EVT_PLACEMENT).value != 1) {
                        refused++;
                    }
                }
            }
            assertEquals(0, refused, "clients refused the placement their departed predecessor had");
        } finally {
            server.stop();
        }
    }

    @Test
    void withRobotsInteractOffTwoRobotsArePlacedOnTheSameSpot() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true",
                "robotsInteract=false");
        try (RawClient a = RawClient.connected(server.getPort()); RawClient b = RawClient.connected(server.getPort())) {
            a.sendBody();
            a.sendPlacement(TestServer.placementName(1));
            RawClient.Event placed = a.awaitEvent(RawClient.EVT_PLACEMENT);
            assertEquals(1, placed.value);
            a.sendInterlock(placed.interlock);
            b.sendBody();
            b.sendPlacement(TestServer.placementName(1));
            assertEquals(1, b.awaitEvent(RawClient.EVT_PLACEMENT).value, "as in RP1 0.60, robots overlap");
        } finally {
            server.stop();
        }
    }
}
