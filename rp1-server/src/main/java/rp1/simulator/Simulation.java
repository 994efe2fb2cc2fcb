package rp1.simulator;

import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;

import rp1.rossum.RsConnection;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.simulator.scheduler.Interlock;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.session.ClientSession;
import rp1.simulator.world.World;

/**
 * A running simulation, headless: the world (floor plan and robots), the scheduler that advances it,
 * the interlock, and the client sessions. Transports (sockets, in-process pipes) attach clients with
 * {@link #attach}; a view observes the world through {@link World#addListener}; one thread runs
 * {@link #run()}.
 */
public final class Simulation {
    private final SimulationSettings settings;
    private final Scheduler scheduler;
    private final Interlock interlock;
    private final World world;
    private final RsLogInterface log;
    private final List<ClientSession> sessions = new CopyOnWriteArrayList<>();

    public Simulation(RsPlan plan, SimulationSettings settings, RsLogInterface log) {
        this.settings = settings;
        this.log = log;
        this.scheduler = new Scheduler(settings.newClock());
        this.interlock = settings.interlock ? new Interlock(scheduler) : null;
        this.world = new World(plan, scheduler, settings.modelingInterval, new Random(settings.randomSeed));
    }

    public SimulationSettings getSettings() {
        return settings;
    }

    public Scheduler getScheduler() {
        return scheduler;
    }

    public World getWorld() {
        return world;
    }

    /** The interlock, or null when it is off. */
    public Interlock getInterlock() {
        return interlock;
    }

    public RsLogInterface getLog() {
        return log;
    }

    /** The current simulation time. */
    public double getSimTime() {
        return scheduler.now();
    }

    /**
     * Attaches a client connection (after its handshake, if any): its requests drive the simulation
     * and it receives its robot's events. Start the connection's {@code run()} afterwards.
     */
    public ClientSession attach(RsConnection connection, String description) {
        connection.setLogger(log);
        ClientSession session = new ClientSession(world, scheduler, interlock, connection, log, description);
        sessions.add(session);
        session.setCloseListener(() -> sessions.remove(session));
        return session;
    }

    /** The sessions of the clients currently connected. */
    public List<ClientSession> getSessions() {
        return sessions;
    }

    /** Starts the clock at simulation time 0 and runs tasks until {@link #shutdown()}. */
    public void run() {
        scheduler.startClock();
        scheduler.runLoop();
    }

    /**
     * Runs tasks until {@link #shutdown()}, but with the clock stopped until {@link #startClock()}:
     * clients can connect and send their first requests, all stamped at time 0, before anything moves.
     */
    public void runPaused() {
        scheduler.runLoop();
    }

    /** Starts (or restarts) the simulation clock. */
    public void startClock() {
        scheduler.startClock();
    }

    /** Stops the scheduler; {@link #run()} returns. */
    public void shutdown() {
        scheduler.shutdown();
    }

    /**
     * A mouse press on the view at world point (x, y): every client with a robot that subscribed to
     * mouse clicks gets the event, stamped with the time of the press.
     */
    public void mouseClick(int button, int clickCount, double x, double y) {
        RsMouseClickEvent e = new RsMouseClickEvent(scheduler.now(), button, clickCount, x, y);
        scheduler.scheduleImmediate(t -> {
            for (ClientSession s : sessions) {
                if (s.getRobot() != null) {
                    s.sendIfSubscribed(e);
                }
            }
        });
    }

    /** Clears every paint trail (the view's "Remove Paint Trails"). */
    public void removePaintTrails() {
        scheduler.scheduleImmediate(t -> world.removePaintTrails());
    }
}
