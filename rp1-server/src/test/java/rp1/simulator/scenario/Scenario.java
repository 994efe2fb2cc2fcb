package rp1.simulator.scenario;

import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.simulator.net.ClientConnection;
import rp1.simulator.net.InProcessClient;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * A whole simulation in one process for scenario tests: a floor plan, the simulation running on its
 * own thread, and clients connected through the real request path: an {@code RsClient} and an
 * {@code RsConnection} over in-memory pipes, or (with the system property
 * {@code rp1.scenario.delivery=direct}) linked directly, their handlers called by the simulation. By
 * default it runs in lockstep with the interlock, so every run of the same scenario produces the same
 * events, whichever way they are delivered; every body numbers its parts from 1 (RsBodyPart).
 */
public final class Scenario implements AutoCloseable {
    /** The system property choosing how clients are connected: "pipes" (the default) or "direct". */
    public static final String DELIVERY = "rp1.scenario.delivery";

    private final Simulation simulation;
    private final Thread schedulerThread;
    private final boolean direct = "direct".equals(System.getProperty(DELIVERY, "pipes"));
    private final List<ScenarioClient> clients = new ArrayList<>();
    private final List<Thread> threads = new ArrayList<>();
    private final List<InProcessClient> links = new ArrayList<>();
    private final List<Runnable> closers = new ArrayList<>();
    private boolean started;

    private Scenario(RsPlan plan, SimulationSettings settings) {
        simulation = new Simulation(plan, settings, QUIET);
        schedulerThread = new Thread(simulation::runPaused, "scenario-scheduler");
        schedulerThread.setDaemon(true);
        schedulerThread.start();
    }

    /** A lockstep simulation of {@code planText} with the default modelling interval of 0.05 s. */
    public static Scenario lockstep(String planText) {
        return new Scenario(plan(planText), SimulationSettings.lockstep(0.05, 1L));
    }

    /** A simulation of {@code planText} with the given settings. */
    public static Scenario with(String planText, SimulationSettings settings) {
        return new Scenario(plan(planText), settings);
    }

    /** A lockstep simulation of one of the floor plans shipped in FloorPlans/. */
    public static Scenario shippedPlan(String fileName) {
        try {
            Path root = Paths.get(System.getProperty("rp1.root", "."));
            return new Scenario(RsPlanParser.parseFile(root.resolve("FloorPlans").resolve(fileName)),
                    SimulationSettings.lockstep(0.05, 1L));
        } catch (IOException | RsParsingException e) {
            throw new IllegalStateException(e);
        }
    }

    static RsPlan plan(String text) {
        try {
            return RsPlanParser.parse(text, "scenario");
        } catch (RsParsingException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    public Simulation simulation() {
        return simulation;
    }

    /**
     * Starts the clock once every client's first requests have been applied (their pipes to the
     * server drained, the inputs they became applied), so they are all stamped at time 0 whatever the
     * threads did. Waiting for an event does this implicitly.
     */
    public synchronized void go() {
        if (started) {
            return;
        }
        long deadline = System.nanoTime() + 10_000_000_000L;
        for (InProcessClient link : links) {
            while (!link.isDrained()) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("a client's requests were not read within 10 s");
                }
                Thread.onSpinWait();
            }
        }
        while (!simulation.getInputs().isSettled()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the clients' first requests were not applied within 10 s");
            }
            Thread.onSpinWait();
        }
        started = true;
        simulation.startClock();
    }

    /**
     * Connects {@code client} in-process, sends its body and registers its recorders, then starts its
     * event loop. Requests the test sends afterwards go through the real protocol.
     */
    public <C extends ScenarioClient> C connect(C client) {
        String description = "scenario client " + (clients.size() + 1);
        if (direct) {
            ClientConnection connection = new ClientConnection(description);
            simulation.attach(connection, description, Simulation.Link.DIRECT);
            connection.connectDirect(client, t -> {
                throw new AssertionError("a handler of " + description + " failed", t);
            });
            closers.add(() -> connection.close("the scenario closed it"));
        } else {
            InProcessClient link = new InProcessClient(simulation, client, description, false);
            links.add(link);
            closers.add(link::close);
        }
        client.join();
        client.beforeWaiting(this::go);
        if (!direct) {
            start(client, "scenario-client");
        }
        clients.add(client);
        return client;
    }

    /** Ends the connection of the client connected {@code index}-th (from 0), as if it went away. */
    public void closeClient(int index) {
        closers.get(index).run();
    }

    private void start(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        t.start();
        threads.add(t);
    }

    @Override
    public void close() {
        simulation.shutdown();
        for (Runnable closer : closers) {
            closer.run();
        }
        Transcripts.record(clients);
    }

    /** A log that drops everything. */
    static final RsLogInterface QUIET = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
        }
    };
}
