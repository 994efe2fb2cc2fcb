package rp1.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * How long a plan from a map image takes to read, and how much heap its walls and the world built on
 * them hold (docs/performance.md, "Plans from maps"). Arguments: {@code IMAGE=METRES} pairs, the
 * image's width in metres as a Stage world gives it. Run it in a JVM of its own:
 * {@code java -cp "$(gradle -q :rp1-server:printBenchClasspath)" rp1.bench.MapLoad cave.png=16 ...}.
 */
public final class MapLoad {
    private static final int TIMED = 10;
    private static final RsLogAdapter QUIET = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
            // the figures are the output
        }
    };

    private MapLoad() {
    }

    /** Prints one line per map: walls, first and best read, heap held by the plan and by the world. */
    public static void main(String[] args) throws Exception {
        Path dir = Files.createTempDirectory("rp1-maps");
        try {
            for (String arg : args) {
                String[] imageAndMetres = arg.split("=", 2);
                Path image = Path.of(imageAndMetres[0]).toAbsolutePath();
                double metres = Double.parseDouble(imageAndMetres[1]);
                int width = javax.imageio.ImageIO.read(image.toFile()).getWidth();
                Path yaml = dir.resolve(image.getFileName() + ".yaml");
                Files.writeString(yaml, "image: " + image + "\nresolution: " + (metres / width) + "\n");
                try {
                    measure(image.getFileName().toString(), metres, yaml);
                } finally {
                    Files.delete(yaml);
                }
            }
        } finally {
            Files.delete(dir);
        }
    }

    private static void measure(String name, double metres, Path yaml) throws Exception {
        long t0 = System.nanoTime();
        RsPlan first = RsPlanParser.parseFile(yaml);
        double firstMs = (System.nanoTime() - t0) * 1e-6;
        double best = Double.MAX_VALUE;
        for (int i = 0; i < TIMED; i++) {
            long t = System.nanoTime();
            RsPlanParser.parseFile(yaml);
            best = Math.min(best, (System.nanoTime() - t) * 1e-6);
        }
        first = null;
        long before = usedAfterGc();
        RsPlan plan = RsPlanParser.parseFile(yaml);
        long withPlan = usedAfterGc();
        long t = System.nanoTime();
        Simulation simulation = new Simulation(plan, SimulationSettings.lockstep(0.05, 1L), QUIET);
        double worldMs = (System.nanoTime() - t) * 1e-6;
        long withWorld = usedAfterGc();
        System.out.printf(Locale.ROOT, "%s at %.0f m: %d walls; read first %.0f ms, then best %.0f ms; world built in %.0f ms;"
                + " heap: plan %.1f MB, world %.1f MB more%n", name, metres, plan.getWallArray().length, firstMs, best,
                worldMs, (withPlan - before) / 1e6, (withWorld - withPlan) / 1e6);
        if (simulation.getWorld().getPlan() != plan) {
            throw new IllegalStateException("the world holds another plan");
        }
    }

    private static long usedAfterGc() throws InterruptedException {
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
        }
        return memory.getHeapMemoryUsage().getUsed();
    }
}
