package rp1.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Locale;

import rp1.simulator.launch.RunningServer;

/**
 * Simulated seconds per wall second with N {@link Wanderer}s in the 40 m benchmark arena: loaded
 * in-process (direct delivery), headless, interlock on, {@code simulationSpeed=max}. Run as a process
 * of its own ({@code Throughput N SECONDS [DELIVERY [PLAN]]}), so that its memory figures are its own:
 * heap used after a collection, and the process's resident set. PLAN replaces the arena (a path, such
 * as a plan on a map image).
 */
public final class Throughput {
    private static final long PLACEMENT_TIMEOUT_MILLIS = 600_000;

    private Throughput() {
    }

    public static void main(String[] args) throws Exception {
        int robots = Integer.parseInt(args[0]);
        double seconds = Double.parseDouble(args[1]);
        String delivery = args.length > 2 ? args[2] : "auto";
        String plan = args.length > 3 ? args[3] : "arena40.txt";
        StringBuilder names = new StringBuilder("dlcName=");
        for (int i = 0; i < robots; i++) {
            names.append(i == 0 ? "" : ",").append(Wanderer.class.getName());
        }
        long startup = System.nanoTime();
        RunningServer server = BenchServer.start("floorPlanFileName=" + plan, "simulationSpeed=max",
                "interlockEnabled=true", "dlcEnabled=true", names.toString(), "enableNetworkClients=false",
                "connectTimeout=600", "dlcDelivery=" + delivery);
        try {
            long deadline = System.currentTimeMillis() + PLACEMENT_TIMEOUT_MILLIS;
            while (Wanderer.PLACED.get() < robots && System.currentTimeMillis() < deadline) {
                Thread.sleep(10);
            }
            double placing = (System.nanoTime() - startup) * 1e-9;
            double s0 = server.getSimulation().getSimTime();
            long e0 = Wanderer.EVENTS.get();
            long t0 = System.nanoTime();
            Thread.sleep((long) (seconds * 1000));
            double wall = (System.nanoTime() - t0) * 1e-9;
            double simulated = server.getSimulation().getSimTime() - s0;
            long events = Wanderer.EVENTS.get() - e0;
            System.gc();
            Runtime rt = Runtime.getRuntime();
            long heap = rt.totalMemory() - rt.freeMemory();
            System.out.printf(Locale.ROOT, "%6d robots (%s delivery, %d placed in %.1f s): %,12.2f simulated s per wall s,"
                    + " %,10.0f events/s, heap used %,d MB, resident %,d MB, -Xmx%s%n", robots, delivery, Wanderer.PLACED.get(),
                    placing, simulated / wall, events / wall, heap >> 20, residentMegabytes(), maxHeap());
        } finally {
            server.stop();
        }
        System.exit(0);
    }

    /** The process's resident set size (Linux), or -1. */
    static long residentMegabytes() {
        try {
            for (String line : Files.readAllLines(Paths.get("/proc/self/status"), StandardCharsets.US_ASCII)) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) >> 10;
                }
            }
        } catch (IOException | NumberFormatException e) {
            return -1;
        }
        return -1;
    }

    private static String maxHeap() {
        return (Runtime.getRuntime().maxMemory() >> 20) + "m";
    }
}
