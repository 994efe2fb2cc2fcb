package rp1demo;

import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsBody;
import rp1.rossum.RsClient;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRunnable;
import rp1.rossum.RsTransform;
import rp1.simulator.net.InProcessClient;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;
import rp1.simulator.world.Robot;

/**
 * One demo robot in a headless lockstep simulation of a shipped floor plan, with the interlock on,
 * connected in-process as the server loads it: the demo's {@code initialize()} runs, its first
 * requests are read, then its event loop starts and the clock with it. The demo logs into this
 * run's log, which a failing test prints.
 */
public final class DemoRun implements AutoCloseable {
    /** Seconds between motion evaluations, as with the default modelling frame rate of 20 Hz. */
    static final double STEP = 0.05;

    private final Simulation simulation;
    private final InProcessClient link;
    private final CapturedLog log = new CapturedLog();
    private final EventRecorder recorder = new EventRecorder();

    private DemoRun(String planFile, RsRunnable demo, RsClient client, BodySource body) throws Exception {
        simulation = new Simulation(plan(planFile), SimulationSettings.lockstep(STEP, 1L), log);
        start(simulation::runPaused, "simulation");
        link = new InProcessClient(simulation, demo, demo.getClass().getSimpleName(), true);
        recorder.attachFirst(client);
        demo.initialize();
        recorder.attachSensors(client, body.body());
        if (!link.awaitDrained(10_000)) {
            throw new AssertionError("the demo's first requests were not read within 10 s");
        }
        start(demo, "demo");
        simulation.startClock();
    }

    /** Where a demo keeps its body (available once it has initialized). */
    public interface BodySource {
        RsBody body();
    }

    /**
     * Starts {@code demo} on {@code planFile} (a file of FloorPlans/); {@code client} is the
     * {@code RsClient} inside it, which gets the recording handlers.
     */
    public static DemoRun start(String planFile, RsRunnable demo, RsClient client, BodySource body) throws Exception {
        return new DemoRun(planFile, demo, client, body);
    }

    /** A shipped floor plan; the build gives the repository root as rp1.root, else it is the parent directory. */
    private static RsPlan plan(String file) throws IOException, RsParsingException {
        Path root = Paths.get(System.getProperty("rp1.root", ".."));
        return RsPlanParser.parseFile(root.resolve("FloorPlans").resolve(file));
    }

    private void start(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        t.start();
    }

    public Simulation simulation() {
        return simulation;
    }

    public EventRecorder events() {
        return recorder;
    }

    /** The demo's robot in the simulated world. */
    public Robot robot() {
        return simulation.getWorld().getRobots().get(0);
    }

    /**
     * Calls {@code watcher} with the robot's pose at every change of the world while the robot is
     * on the floor (on the simulation's thread: at each motion step, among others).
     */
    public void watchRobot(Consumer<RsTransform> watcher) {
        simulation.getWorld().addListener((world, t) -> {
            if (!world.getRobots().isEmpty() && world.getRobots().get(0).isPlaced()) {
                watcher.accept(world.getRobots().get(0).pose());
            }
        });
    }

    /** Simulated seconds so far. */
    public double simTime() {
        return simulation.getSimTime();
    }

    /** What the demo logged, one line each, with simulated times. */
    public String logText() {
        return log.text();
    }

    /** Waits (wall time, at most {@code seconds}) until {@code condition} holds. */
    public void waitUntil(BooleanSupplier condition, double seconds, String what) throws InterruptedException {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError(what + " did not happen within " + seconds + " s (simulated time "
                        + simTime() + " s); log:\n" + logText());
            }
            Thread.sleep(2);
        }
    }

    @Override
    public void close() {
        simulation.shutdown();
        link.close();
    }

    /** The simulation's log: collects lines, each with the simulated time it was written at. */
    private final class CapturedLog extends RsLogAdapter {
        /** -Drp1.demo.echo=true prints the demos' log lines as they come, for watching a test run. */
        private static final boolean ECHO = Boolean.getBoolean("rp1.demo.echo");

        private final StringBuilder lines = new StringBuilder();

        CapturedLog() {
            super(true);
        }

        @Override
        public synchronized void logIt(String level, String message) {
            double t = simulation == null ? 0.0 : simulation.getSimTime();
            String line = String.format(Locale.ROOT, "%s %9.3f %s%n", level, t, message);
            lines.append(line);
            if (ECHO) {
                System.out.print(line);
            }
        }

        synchronized String text() {
            return lines.toString();
        }
    }
}
