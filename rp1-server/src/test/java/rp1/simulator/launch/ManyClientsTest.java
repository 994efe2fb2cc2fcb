package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;

/** Many network clients at once: each connects, is placed and drives, and none disturbs another. */
@Timeout(60)
class ManyClientsTest {
    private static final int CLIENTS = TestServer.PLACEMENTS;

    @TempDir
    Path dir;

    @Test
    void fiftyClientsConnectPlaceAndMoveAtOnce() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=10");
        ExecutorService pool = Executors.newFixedThreadPool(CLIENTS);
        try {
            CountDownLatch go = new CountDownLatch(1);
            List<Future<RsMotionHaltedEvent>> drives = new ArrayList<>();
            for (int i = 1; i <= CLIENTS; i++) {
                int n = i;
                drives.add(pool.submit(drive(server.getPort(), n, go)));
            }
            go.countDown();
            for (int i = 1; i <= CLIENTS; i++) {
                RsMotionHaltedEvent halted = drives.get(i - 1).get();
                assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt, "robot " + i);
                assertEquals(TestServer.placementX(i) + 0.5, halted.x, 1e-9, "robot " + i + " drove 0.5 m east");
                assertEquals(TestServer.placementY(i), halted.y, 1e-9);
            }
            String log = TestServer.log(dir);
            assertEquals(CLIENTS, log.split(" connected \\(client id 0, key 0\\)\n", -1).length - 1, "one line per connection");
        } finally {
            pool.shutdownNow();
            assertEquals(ExitStatus.OK, server.stop());
        }
    }

    /** One client: connect, body, placement at pN, then 0.5 m at 0.5 m/s once placed. */
    private static Callable<RsMotionHaltedEvent> drive(int port, int n, CountDownLatch go) {
        return () -> {
            go.await();
            TcpRobot robot = TcpRobot.connect(port, "robot " + n);
            robot.addPlacementEventHandler(e -> robot.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 1.0)));
            robot.startLoop();
            robot.sendPlacementRequest(TestServer.placementName(n));
            RsPlacementEvent placed = robot.await(RsPlacementEvent.class, e -> true);
            assertTrue(placed.valid, "placed at " + placed.name);
            RsMotionHaltedEvent halted = robot.await(RsMotionHaltedEvent.class, e -> true);
            robot.leave();
            return halted;
        };
    }
}
