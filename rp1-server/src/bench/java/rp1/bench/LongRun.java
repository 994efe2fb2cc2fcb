package rp1.bench;

import java.util.Locale;

import rp1.simulator.launch.RunningServer;

/**
 * Whether a long run keeps its pace: one {@link Wanderer} for 100,000 simulated seconds in the arena,
 * the rate of the first tenth against the last tenth. Run as a process of its own
 * ({@code LongRun SECONDS}).
 */
public final class LongRun {
    private LongRun() {
    }

    public static void main(String[] args) throws Exception {
        double total = Double.parseDouble(args[0]);
        RunningServer server = BenchServer.start("floorPlanFileName=arena40.txt", "simulationSpeed=max",
                "interlockEnabled=true", "dlcEnabled=true", "dlcName=" + Wanderer.class.getName(),
                "enableNetworkClients=false", "maxSimulationTime=" + total);
        double[] marks = {0.0, 0.1 * total, 0.9 * total, total};
        long[] wallAt = new long[marks.length];
        long[] eventsAt = new long[marks.length];
        int next = 0;
        while (next < marks.length) {
            double t = server.getSimulation().getScheduler().recordedTime();
            while (next < marks.length && (t >= marks[next] || server.hasExited())) {
                wallAt[next] = System.nanoTime();
                eventsAt[next] = Wanderer.EVENTS.get();
                next++;
            }
            Thread.sleep(1);
        }
        double first = 0.1 * total / ((wallAt[1] - wallAt[0]) * 1e-9);
        double last = 0.1 * total / ((wallAt[3] - wallAt[2]) * 1e-9);
        System.out.printf(Locale.ROOT, "one wanderer for %,.0f simulated s: first tenth %,.0f simulated s per wall s"
                + " (%,.0f events/s), last tenth %,.0f (%,.0f events/s): %+.1f%%%n", total, first,
                (eventsAt[1] - eventsAt[0]) / ((wallAt[1] - wallAt[0]) * 1e-9), last,
                (eventsAt[3] - eventsAt[2]) / ((wallAt[3] - wallAt[2]) * 1e-9), 100.0 * (last - first) / first);
        server.stop();
        System.exit(0);
    }
}
