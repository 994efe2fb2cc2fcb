package rp1.bench;

import java.util.Locale;

import rp1.simulator.launch.RunningServer;

/**
 * Simulated seconds per wall second with N wanderers in the contest arena: headless, interlock on,
 * {@code simulationSpeed=max}, the clients loaded in-process.
 */
final class Throughput {
    private static final long PLACEMENT_TIMEOUT_MILLIS = 120_000;

    private Throughput() {
    }

    static void run(int robots, double seconds) throws Exception {
        Wanderer.EVENTS.set(0);
        Wanderer.PLACED.set(0);
        StringBuilder names = new StringBuilder("dlcName=");
        for (int i = 0; i < robots; i++) {
            names.append(i == 0 ? "" : ",").append(Wanderer.class.getName());
        }
        RunningServer server = BenchServer.start("floorPlanFileName=contest.txt", "simulationSpeed=max",
                "interlockEnabled=true", "dlcEnabled=true", names.toString(), "enableNetworkClients=false",
                "connectTimeout=120");
        try {
            long deadline = System.currentTimeMillis() + PLACEMENT_TIMEOUT_MILLIS;
            while (Wanderer.PLACED.get() < robots && System.currentTimeMillis() < deadline) {
                Thread.sleep(10);
            }
            Thread.sleep(500);
            double s0 = server.getSimulation().getSimTime();
            long e0 = Wanderer.EVENTS.get();
            long t0 = System.nanoTime();
            Thread.sleep((long) (seconds * 1000));
            double wall = (System.nanoTime() - t0) * 1e-9;
            double simulated = server.getSimulation().getSimTime() - s0;
            long events = Wanderer.EVENTS.get() - e0;
            Runtime rt = Runtime.getRuntime();
            long heap = rt.totalMemory() - rt.freeMemory();
            System.out.printf(Locale.ROOT,
                    "%4d robots (%d placed): %,10.2f simulated s per wall s, %,9.0f events/s, heap used %,d MB%n",
                    robots, Wanderer.PLACED.get(), simulated / wall, events / wall, heap >> 20);
        } finally {
            server.stop();
        }
    }
}
