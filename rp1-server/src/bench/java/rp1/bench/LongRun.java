package rp1.bench;

import java.util.Locale;

import rp1.simulator.launch.RunningServer;

/**
 * Whether a long run keeps its pace: one {@link Wanderer} for 100,000 simulated seconds in the contest
 * arena (small and walled all round, so that the robot's work per simulated second is much the same
 * throughout; in the large arena open ground and pillars alternate), the rate of the first tenth
 * against the last tenth. The first tenth is also measured after 20,000 simulated seconds of warming
 * up in the same run: the JIT compiler takes the first second or two of wall time. Run as a process
 * of its own ({@code LongRun SECONDS}).
 */
public final class LongRun {
    private static final double WARM_UP = 20_000;

    private LongRun() {
    }

    public static void main(String[] args) throws Exception {
        double total = Double.parseDouble(args[0]);
        RunningServer server = BenchServer.start("floorPlanFileName=contest.txt", "simulationSpeed=max",
                "interlockEnabled=true", "dlcEnabled=true", "dlcName=" + Wanderer.class.getName(),
                "enableNetworkClients=false", "maxSimulationTime=" + (WARM_UP + total));
        double[] marks = {Double.MIN_VALUE, 0.1 * total, WARM_UP, WARM_UP + 0.1 * total, WARM_UP + 0.9 * total,
            WARM_UP + total};
        long[] wallAt = new long[marks.length];
        int next = 0;
        while (next < marks.length) {
            double t = server.getSimulation().getScheduler().recordedTime();
            while (next < marks.length && (t >= marks[next] || server.hasExited())) {
                wallAt[next++] = System.nanoTime();
            }
            Thread.sleep(1);
        }
        double cold = rate(0.1 * total, wallAt[0], wallAt[1]);
        double first = rate(0.1 * total, wallAt[2], wallAt[3]);
        double last = rate(0.1 * total, wallAt[4], wallAt[5]);
        System.out.printf(Locale.ROOT, "one wanderer for %,.0f simulated s after %,.0f s of warming up: first tenth"
                + " %,.0f simulated s per wall s, last tenth %,.0f: %+.1f%% (the first tenth of a cold run: %,.0f)%n",
                total, WARM_UP, first, last, 100.0 * (last - first) / first, cold);
        server.stop();
        System.exit(0);
    }

    private static double rate(double simulated, long from, long to) {
        return simulated / ((to - from) * 1e-9);
    }
}
