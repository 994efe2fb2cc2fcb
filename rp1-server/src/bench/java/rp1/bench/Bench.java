package rp1.bench;

import java.io.IOException;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

import rp1.rossum.RsProperties;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.StartupException;

/**
 * {@code gradle bench}: the figures of docs/performance.md. Arguments: {@code all} (default), or any of
 * {@code latency}, {@code connect}, {@code cold}, {@code pacing}, {@code throughput}, {@code longrun},
 * {@code network}, {@code scale} (the peers' "scale arena" workload, {@link ScaleArena});
 * {@code robots=1,100,1000} chooses the robot counts of the throughput and scale runs, {@code xmx=512m}
 * their heap. Not in {@code all}: {@code peers[=DIR] [rounds=N]}, the scale arena side by side with the
 * peer simulators whose scripts are in DIR or {@code $RP1_PEERS} ({@link SideBySide}; robots 1, 10, 100
 * and 1,000 unless {@code robots=} says). Figures only; nothing is asserted.
 */
public final class Bench {
    private static final double MEASURE_SECONDS = 3.0;
    private static final int WINDOWS = 5;

    private Bench() {
    }

    public static void main(String[] args) throws Exception {
        List<String> what = new ArrayList<>();
        List<Integer> robots = List.of(1, 10, 100, 1000, 10000);
        List<Integer> peerRobots = List.of(1, 10, 100, 1000);
        String xmx = "512m";
        int rounds = 3;
        String peers = null;
        boolean sideBySide = false;
        for (String a : args) {
            if (a.startsWith("robots=")) {
                robots = parseCounts(a.substring("robots=".length()));
                peerRobots = robots;
            } else if (a.startsWith("rounds=")) {
                rounds = Integer.parseInt(a.substring("rounds=".length()));
            } else if (a.equals("peers") || a.startsWith("peers=")) {
                sideBySide = true;
                peers = a.startsWith("peers=") ? a.substring("peers=".length()) : null;
            } else if (a.startsWith("xmx=")) {
                xmx = a.substring("xmx=".length());
            } else {
                what.add(a);
            }
        }
        boolean all = (what.isEmpty() && !sideBySide) || what.contains("all");
        System.out.printf(Locale.ROOT, "RP1 server benchmark, %s, %d processors, Java %s%n",
                LocalDate.now(), Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"));
        if (all || what.contains("latency")) {
            latency();
        }
        if (all || what.contains("connect")) {
            connect();
        }
        if (all || what.contains("cold")) {
            ColdStart.run(3);
        }
        if (all || what.contains("pacing")) {
            Pacing.run();
        }
        if (all || what.contains("throughput")) {
            for (int n : robots) {
                int status = Child.run(xmx, Throughput.class, System.out::println, String.valueOf(n),
                        String.valueOf(n >= 1000 ? 2 * MEASURE_SECONDS : MEASURE_SECONDS));
                if (status != 0) {
                    System.out.println(n + " robots: the run failed with status " + status);
                }
            }
        }
        if (all || what.contains("scale")) {
            for (int n : robots) {
                int status = Child.run(xmx, ScaleArena.class, System.out::println, String.valueOf(n),
                        String.valueOf(ScaleArena.simulatedFor(n)), String.valueOf(ScaleArena.arenaFor(n)));
                if (status != 0) {
                    System.out.println(n + " robots in the scale arena: the run failed with status " + status);
                }
            }
        }
        if (sideBySide) {
            SideBySide.run(SideBySide.peersFolder(peers, System.getenv(SideBySide.PEERS_VARIABLE)), peerRobots, rounds, xmx);
        }
        if (all || what.contains("longrun")) {
            Child.run(xmx, LongRun.class, System.out::println, "100000");
        }
        if (all || what.contains("network")) {
            NetworkClients.run(100, MEASURE_SECONDS);
        }
        System.exit(0);
    }

    private static List<Integer> parseCounts(String list) {
        List<Integer> counts = new ArrayList<>();
        for (String s : list.split(",")) {
            counts.add(Integer.parseInt(s.trim()));
        }
        return Collections.unmodifiableList(counts);
    }

    /**
     * Interlocked round trips against plain ping-pongs, over loopback TCP and in-process. The machine
     * may be shared, so both are measured in alternating one-second windows and the best window of
     * each is compared, as well as the medians.
     */
    private static void latency() throws Exception {
        RunningServer tcpServer = BenchServer.start("simulationSpeed=max", "interlockEnabled=true");
        try (Baselines socket = Baselines.socket(); RoundTripClient overTcp = connect(tcpServer.getPort())) {
            compare("loopback TCP", "plain socket int ping-pong", socket, overTcp);
        } finally {
            tcpServer.stop();
        }
        RoundTripClient.latest = null;
        RunningServer inProcess = BenchServer.start("simulationSpeed=max", "interlockEnabled=true", "dlcEnabled=true",
                "dlcName=" + RoundTripClient.class.getName(), "enableNetworkClients=false");
        try (Baselines piped = Baselines.piped()) {
            while (RoundTripClient.latest == null) {
                Thread.sleep(10);
            }
            compare("in-process", "PipedInputStream int ping-pong", piped, RoundTripClient.latest);
        } finally {
            inProcess.stop();
        }
    }

    private static RoundTripClient connect(int port) throws IOException {
        RoundTripClient client = new RoundTripClient();
        client.setLogger(null);
        RsProperties p = new RsProperties();
        p.hostName = "127.0.0.1";
        p.port = port;
        client.initialize(p);
        Thread loop = new Thread(client, "round trips");
        loop.setDaemon(true);
        loop.start();
        return client;
    }

    private static void compare(String where, String baselineName, RoundTrips baseline, RoundTrips interlocked)
            throws Exception {
        baseline.measure(0.5);
        interlocked.measure(0.5);
        double[] b = new double[WINDOWS];
        double[] r = new double[WINDOWS];
        for (int i = 0; i < WINDOWS; i++) {
            b[i] = baseline.measure(1.0);
            r[i] = interlocked.measure(1.0);
        }
        Arrays.sort(b);
        Arrays.sort(r);
        double bestB = b[WINDOWS - 1];
        double bestR = r[WINDOWS - 1];
        double medB = b[WINDOWS / 2];
        double medR = r[WINDOWS / 2];
        System.out.printf(Locale.ROOT, "%s: %s %,.0f/s (median %,.0f); interlocked round trips %,.0f/s (median %,.0f); "
                + "ratio of bests %.2f, of medians %.2f%n", where, baselineName, bestB, medB, bestR, medR,
                bestR / bestB, medR / medB);
    }

    /**
     * 20 clients in a row: connect, handshake, body, placement. The first run pays for class loading
     * and compilation; then five more on fresh servers, best and median reported.
     */
    private static void connect() throws IOException, StartupException, InterruptedException {
        double cold = placeTwenty();
        double[] warm = new double[WINDOWS];
        for (int i = 0; i < WINDOWS; i++) {
            warm[i] = placeTwenty();
        }
        Arrays.sort(warm);
        System.out.printf(Locale.ROOT, "20 clients connected, bodies uploaded and placed, one after another: "
                + "%.1f ms (best of %d), median %.1f ms, first run in a cold JVM %.1f ms%n", warm[0], WINDOWS,
                warm[WINDOWS / 2], cold);
    }

    private static double placeTwenty() throws IOException, StartupException, InterruptedException {
        RunningServer server = BenchServer.start();
        try {
            return Connecting.placeInARow(server.getPort(), 20);
        } finally {
            server.stop();
        }
    }
}
