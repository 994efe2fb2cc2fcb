package rp1.bench;

import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;

import rp1.simulator.launch.RunningServer;

/**
 * The peers' "scale arena" workload (docs/performance.md) with RP1's own robot and plan: N {@link
 * ScaleWanderer}s in a square arena (40 m, or larger for larger crowds) with diamond pillars on a 5 m
 * grid, loaded in-process, headless, interlock on, {@code simulationSpeed=max}. Run as a process of its
 * own ({@code ScaleArena N SIMULATED [ARENA [EVENTLOG]]}) so that its memory figures are its own; with
 * EVENTLOG it only writes the event log of the first SIMULATED seconds (or a little more), to compare
 * two builds' runs line by line up to a time. The clock is
 * counted from the moment all are placed. A crowd's cost changes as it moves (robots meet, press and
 * part), so the measure is over simulated time, the same stretch whatever the machine's speed: after
 * a warm-up of a fifth of SIMULATED seconds, the wall time the next SIMULATED seconds take; printed as
 * simulated seconds per wall second (and per CPU second of the Java threads, which a shared
 * machine disturbs less), with events per second. The figure is the compiled steady state: before the
 * measured world, the same world runs twice ({@link #WARM_UP_WORLDS}), each time until the compilers
 * have been idle for a second (two seconds at least, twenty at most), and is thrown away, so the
 * optimizing compiler has done its work (a fifth of
 * one robot's 20,000 simulated seconds passes in a tenth of a second, and measured the compiler as
 * much as the simulator).
 */
public final class ScaleArena {
    private static final double WALL = 0.1;
    private static final double PILLAR = 0.4;
    private static final double GRID = 5.0;
    private static final double MARGIN = 0.05;
    private static final long PLACEMENT_TIMEOUT_MILLIS = 900_000;
    /**
     * The run warms up for this part of the simulated time it measures: on a busy machine the compiler
     * takes seconds to reach the hot path.
     */
    private static final double WARM_UP_PART = 5.0;
    /** The longest wait between two looks at the clock. */
    private static final long MAX_POLL_MILLIS = 20;
    /** How long a throwaway copy of the world runs first at least, so that the measured one runs compiled code. */
    private static final long COMPILER_WARM_UP_MILLIS = 2000;
    /** ... and then until the compilers have been idle this long. */
    private static final long COMPILER_QUIET_MILLIS = 1000;
    /** ... but no longer than this. */
    private static final long COMPILER_WARM_UP_MAX_MILLIS = 20_000;
    /**
     * How many throwaway copies of the world run before the measured one. With one, starting the
     * measured world deoptimized the motion step, the contact search and the robot index (placing
     * robots takes paths the first world's steady state never took), and their recompilation, half a
     * second of the optimizing compiler's time, overlapped the measured stretch; a second throwaway
     * world takes that in.
     */
    private static final int WARM_UP_WORLDS = Integer.getInteger("rp1.bench.warmUpWorlds", 2);
    /** A measurement (or its warm-up) that takes longer than this stops there and reports what it got. */
    private static final long MAX_WALL_MILLIS = 300_000;

    private ScaleArena() {
    }

    public static void main(String[] args) throws Exception {
        int robots = Integer.parseInt(args[0]);
        double simulated = Double.parseDouble(args[1]);
        double arena = args.length > 2 ? Double.parseDouble(args[2]) : 40.0;
        String eventLog = args.length > 3 ? args[3] : null;
        Path plan = Files.createTempFile("rp1-scale", ".txt");
        plan.toFile().deleteOnExit();
        Files.write(plan, plan(arena, robots).getBytes(StandardCharsets.UTF_8));
        StringBuilder names = new StringBuilder("dlcName=");
        for (int i = 0; i < robots; i++) {
            names.append(i == 0 ? "" : ",").append(ScaleWanderer.class.getName());
        }
        String[] properties = {"floorPlanFileName=" + plan.toAbsolutePath(), "simulationSpeed=max",
            "interlockEnabled=true", "dlcEnabled=true", names.toString(), "enableNetworkClients=false",
            "connectTimeout=900"};
        for (int w = 0; eventLog == null && w < WARM_UP_WORLDS; w++) {
            RunningServer warmUp = BenchServer.start(properties);
            try {
                awaitPlaced(robots);
                awaitCompilerQuiet();
            } finally {
                warmUp.stop();
                ScaleWanderer.startAnew();
            }
        }
        long startup = System.nanoTime();
        RunningServer server = BenchServer.start(eventLog == null ? properties
                : append(properties, "eventLogFileName=" + eventLog));
        try {
            awaitPlaced(robots);
            double placing = (System.nanoTime() - startup) * 1e-9;
            if (eventLog != null) {
                awaitSimTime(server, simulated, MAX_WALL_MILLIS);
                return;
            }
            double warm = simulated / WARM_UP_PART;
            awaitSimTime(server, warm, MAX_WALL_MILLIS);
            double s0 = server.getSimulation().getSimTime();
            long e0 = ScaleWanderer.EVENTS.get();
            long c0 = cpuNanos();
            long t0 = System.nanoTime();
            awaitSimTime(server, s0 + simulated, MAX_WALL_MILLIS);
            double wall = (System.nanoTime() - t0) * 1e-9;
            double cpu = (cpuNanos() - c0) * 1e-9;
            double done = server.getSimulation().getSimTime() - s0;
            long events = ScaleWanderer.EVENTS.get() - e0;
            System.gc();
            Runtime rt = Runtime.getRuntime();
            long heap = rt.totalMemory() - rt.freeMemory();
            System.out.printf(Locale.ROOT, "scale arena %6d robots, %.1f m (%d placed in %.1f s), simulated %.1f to %.1f s:"
                    + " %,12.2f simulated s per wall s (%,.2f per CPU s), %,10.0f events/s, heap used %,d MB, resident %,d MB,"
                    + " -Xmx%dm%n", robots, arena, ScaleWanderer.PLACED.get(), placing, s0, s0 + done, done / wall, done / cpu,
                    events / wall, heap >> 20,
                    Throughput.residentMegabytes(), rt.maxMemory() >> 20);
        } finally {
            server.stop();
        }
        System.exit(0);
    }

    /**
     * Lets the throwaway world run until the compilers have had nothing to do for
     * {@link #COMPILER_QUIET_MILLIS} (at least {@link #COMPILER_WARM_UP_MILLIS}, at most
     * {@link #COMPILER_WARM_UP_MAX_MILLIS}). A fixed two seconds was not enough on this project's
     * two-core machine: the optimizing compiler's work on the motion step (over half a second for one
     * method) sometimes landed in the measured stretch, and the same build's 1,000-robot figure read
     * anything from 20 to 31.
     */
    private static void awaitCompilerQuiet() throws InterruptedException {
        CompilationMXBean compiler = ManagementFactory.getCompilationMXBean();
        long start = System.currentTimeMillis();
        long quietSince = start;
        long last = compiler.getTotalCompilationTime();
        while (true) {
            Thread.sleep(100);
            long now = System.currentTimeMillis();
            long total = compiler.getTotalCompilationTime();
            if (total != last) {
                last = total;
                quietSince = now;
            }
            if (now - start >= COMPILER_WARM_UP_MAX_MILLIS
                    || (now - start >= COMPILER_WARM_UP_MILLIS && now - quietSince >= COMPILER_QUIET_MILLIS)) {
                return;
            }
        }
    }

    /** Waits until {@code robots} wanderers are placed, or for {@link #PLACEMENT_TIMEOUT_MILLIS} at most. */
    private static void awaitPlaced(int robots) throws InterruptedException {
        long deadline = System.currentTimeMillis() + PLACEMENT_TIMEOUT_MILLIS;
        while (ScaleWanderer.PLACED.get() < robots && System.currentTimeMillis() < deadline) {
            Thread.sleep(5);
        }
    }

    private static String[] append(String[] properties, String more) {
        String[] all = Arrays.copyOf(properties, properties.length + 1);
        all[properties.length] = more;
        return all;
    }

    /**
     * Waits until the simulation's clock reaches {@code time}, or for {@code maxMillis} at most. Reading
     * the clock takes the scheduler's lock, and a reader that finds it held must be woken by the
     * simulation thread (at 1,000 robots, polling every millisecond cost 3–4 % of that thread's time),
     * so it looks rarely while the time is far off and every millisecond only in the last quarter of the
     * way, where the answer's precision lies.
     */
    private static void awaitSimTime(RunningServer server, double time, long maxMillis) throws InterruptedException {
        long start = System.nanoTime();
        long deadline = System.currentTimeMillis() + maxMillis;
        double from = server.getSimulation().getSimTime();
        double now = from;
        while (now < time && System.currentTimeMillis() < deadline) {
            double elapsed = (System.nanoTime() - start) * 1e-9;
            double rate = now > from && elapsed > 0 ? (now - from) / elapsed : 0.0;
            long millis = rate > 0 ? (long) (250.0 * (time - now) / rate) : 1;
            Thread.sleep(Math.max(1, Math.min(MAX_POLL_MILLIS, millis)));
            now = server.getSimulation().getSimTime();
        }
    }

    /**
     * CPU time of the process's Java threads (the simulation's, not the compiler's or the collector's):
     * on a shared machine it tells the work done from the share of the cores the run got.
     */
    private static long cpuNanos() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long sum = 0;
        for (long id : threads.getAllThreadIds()) {
            sum += Math.max(0, threads.getThreadCpuTime(id));
        }
        return sum;
    }

    /** Simulated seconds measured for a crowd: the peers' bench spans (20,000 s for one robot, 30 s for 1,000). */
    static double simulatedFor(int robots) {
        return robots <= 1 ? 20000 : robots <= 10 ? 3000 : robots <= 100 ? 300 : robots <= 1000 ? 30 : 5;
    }

    /** The arena side for a crowd: 40 m, or as large as keeps 1,000 robots' density in 40 m. */
    static double arenaFor(int robots) {
        return robots <= 1000 ? 40.0 : Math.round(40.0 * Math.sqrt(robots / 1000.0) * 10) / 10.0;
    }

    /** The plan: walls, pillars on the 5 m grid, and one placement per robot, "s0" to "sN-1". */
    static String plan(double arena, int robots) {
        StringBuilder s = new StringBuilder("caption: \"Scale arena\";\nunits: meters;\n");
        s.append(wall("south", 0, 0, arena, 0)).append(wall("east", arena, 0, arena, arena))
                .append(wall("north", arena, arena, 0, arena)).append(wall("west", 0, arena, 0, 0));
        int pillars = (int) Math.floor((arena - GRID) / GRID + 1e-9);
        for (int i = 1; i <= pillars; i++) {
            for (int j = 1; j <= pillars; j++) {
                s.append(String.format(Locale.ROOT, "obstacle p%d_%d { polygon: 4, %s; offset: %s, %s; }%n", i, j,
                        PILLAR, i * GRID, j * GRID));
            }
        }
        List<double[]> poses = poses(arena, robots, pillars);
        for (int k = 0; k < poses.size(); k++) {
            double[] p = poses.get(k);
            s.append(String.format(Locale.ROOT, "placement s%d { geometry: %.4f, %.4f, %.2f, %s; }%n", k, p[0], p[1],
                    p[2], ScaleWanderer.RADIUS));
        }
        return s.toString();
    }

    private static String wall(String name, double x0, double y0, double x1, double y1) {
        return String.format(Locale.ROOT, "wall %s { geometry: %s, %s, %s, %s, %s; }%n", name, x0, y0, x1, y1, WALL);
    }

    /**
     * Collision-free start poses from a fixed seed, as the peers' {@code scale_arena.py} draws them: clear
     * of the walls, of each pillar's circumcircle and of each other by {@link #MARGIN}; heading in degrees.
     */
    static List<double[]> poses(double arena, int n, int pillars) {
        Random rng = new Random(1);
        double r = ScaleWanderer.RADIUS + 0.005;
        double lo = WALL / 2 + r + MARGIN;
        double hi = arena - lo;
        double cell = 2 * r + MARGIN;
        Map<Long, List<double[]>> grid = new HashMap<>();
        List<double[]> poses = new ArrayList<>();
        while (poses.size() < n) {
            double x = lo + (hi - lo) * rng.nextDouble();
            double y = lo + (hi - lo) * rng.nextDouble();
            double gx = Math.round(x / GRID) * GRID;
            double gy = Math.round(y / GRID) * GRID;
            if (gx >= GRID && gx <= pillars * GRID && gy >= GRID && gy <= pillars * GRID
                    && Math.hypot(x - gx, y - gy) < PILLAR + r + MARGIN) {
                continue;
            }
            long ci = (long) Math.floor(x / cell);
            long cj = (long) Math.floor(y / cell);
            if (!clash(grid, ci, cj, x, y, cell)) {
                grid.computeIfAbsent(ci * 1_000_003L + cj, k -> new ArrayList<>()).add(new double[] {x, y});
                poses.add(new double[] {x, y, 360 * rng.nextDouble() - 180});
            }
        }
        return poses;
    }

    private static boolean clash(Map<Long, List<double[]>> grid, long ci, long cj, double x, double y, double cell) {
        for (long di = -1; di <= 1; di++) {
            for (long dj = -1; dj <= 1; dj++) {
                for (double[] p : grid.getOrDefault((ci + di) * 1_000_003L + cj + dj, List.of())) {
                    if (Math.hypot(x - p[0], y - p[1]) < cell) {
                        return true;
                    }
                }
            }
        }
        return false;
    }
}
