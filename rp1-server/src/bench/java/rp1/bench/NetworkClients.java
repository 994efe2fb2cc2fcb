package rp1.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import rp1.simulator.launch.RunningServer;

/**
 * Many network clients: N robots over loopback TCP, each with a 0.1 s heartbeat, interlock on,
 * {@code simulationSpeed=max}. The heartbeats of all clients due at one time go out together and are
 * acknowledged in parallel.
 */
final class NetworkClients {
    private NetworkClients() {
    }

    static void run(int clients, double seconds) throws Exception {
        RunningServer server = BenchServer.start("floorPlanFileName=arena40.txt", "simulationSpeed=max",
                "interlockEnabled=true", "waitForClients=" + clients);
        AtomicLong beats = new AtomicLong();
        List<NetRobot> robots = new ArrayList<>();
        try {
            CountDownLatch placed = new CountDownLatch(clients);
            for (int i = 0; i < clients; i++) {
                robots.add(robot(server.getPort(), i, placed, beats));
            }
            if (!placed.await(60, TimeUnit.SECONDS)) {
                throw new IOException("not every robot was placed within 60 s");
            }
            Thread.sleep(300);
            double s0 = server.getSimulation().getSimTime();
            long b0 = beats.get();
            long t0 = System.nanoTime();
            Thread.sleep((long) (seconds * 1000));
            double wall = (System.nanoTime() - t0) * 1e-9;
            System.out.printf(Locale.ROOT, "%d network clients over loopback, 0.1 s heartbeats, interlock, max: %,.1f"
                    + " simulated s per wall s, %,.0f heartbeats/s%n", clients,
                    (server.getSimulation().getSimTime() - s0) / wall, (beats.get() - b0) / wall);
        } finally {
            robots.forEach(NetRobot::leave);
            server.stop();
        }
    }

    private static NetRobot robot(int port, int i, CountDownLatch placed, AtomicLong beats) throws IOException {
        NetRobot c = new NetRobot(port, "net " + i, 0.1, placed);
        c.addHeartbeatEventHandler(e -> beats.incrementAndGet());
        c.sendHeartbeatRequest(0.1);
        return c.place("$random");
    }
}
