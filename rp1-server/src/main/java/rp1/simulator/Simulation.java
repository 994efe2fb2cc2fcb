package rp1.simulator;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import rp1.rossum.RsConnection;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsEvent;
import rp1.simulator.noise.SplitMix;
import rp1.simulator.scheduler.InputQueue;
import rp1.simulator.scheduler.Interlock;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.session.ClientBudgets;
import rp1.simulator.session.ClientInput;
import rp1.simulator.session.ClientSession;
import rp1.simulator.session.Heartbeats;
import rp1.simulator.session.Request;
import rp1.simulator.world.World;

/**
 * A running simulation, headless: the world (floor plan and robots), the scheduler that advances it,
 * the inputs waiting for the next boundary, the interlock, and the client sessions. Transports attach
 * clients with {@link #attach}; a view observes the world through {@link World#addListener} and the
 * observer actions here, and reaches in only through inputs ({@link #mouseClick},
 * {@link #removePaintTrails}: {@link ViewAction}s); one thread runs {@link #run()} (see
 * {@link Scheduler} for which threads may also run tasks).
 */
public final class Simulation {
    /** How long a transport thread may run tasks before leaving the rest to the dispatch loop. */
    private static final long PUMP_BUDGET_NANOS = TimeUnit.MILLISECONDS.toNanos(2);

    /** How a client's connection reaches the simulation, which decides who runs the tasks its messages make due. */
    public enum Link {
        /** A reader thread of its own (in-process pipes): it runs the tasks due after each message itself. */
        READER,
        /**
         * A thread shared with other clients (the network's selector): it runs the due tasks itself
         * after each round of reading ({@link #pump()}).
         */
        SHARED_READER,
        /**
         * An in-process client whose handlers the simulation calls directly: its requests are inputs
         * like any other, and it needs no interlock (a handler returning is the acknowledgement).
         */
        DIRECT
    }

    private final SimulationSettings settings;
    private final Scheduler scheduler;
    private final InputQueue inputs;
    private final Interlock interlock;
    private final World world;
    private final Heartbeats heartbeats;
    private final RsLogInterface log;
    private final List<ClientSession> sessions = new CopyOnWriteArrayList<>();
    private final AtomicInteger clientNumbers = new AtomicInteger();
    private final ClientSession.Host host;
    private final List<EventListener> eventListeners = new CopyOnWriteArrayList<>();
    /** Robots still to be placed before the clock may run ({@code waitForClients}); 0 once it runs. */
    private int waitingFor;
    /** Robots on the floor now, and whether there ever was one (on the thread running tasks). */
    private int placedRobots;
    private boolean robotsPlacedSoFar;
    private volatile Runnable whenDeserted = () -> { };
    private volatile ClientBudgets clientBudgets = ClientBudgets.DEFAULTS;
    private final ReportedResults reportedResults = new ReportedResults();
    private final AskedParameters askedParameters = new AskedParameters();
    /** The first task failure, as {@link #describe} words it; written on the task thread. */
    private volatile String taskFailure;

    public Simulation(RsPlan plan, SimulationSettings settings, RsLogInterface log) {
        this.settings = settings;
        this.log = log;
        this.scheduler = new Scheduler(settings.newClock());
        this.inputs = new InputQueue(scheduler);
        this.interlock = settings.interlock ? new Interlock(scheduler) : null;
        // Mixed: java.util.Random's first draws from consecutive seeds are nearly the same.
        this.world = new World(plan, scheduler, settings.modelingInterval, new Random(SplitMix.mix(settings.randomSeed)),
                settings.robotsInteract);
        this.heartbeats = new Heartbeats(scheduler);
        this.host = new SessionHost();
        scheduler.setFailureHandler(this::taskFailed);
        world.setNoise(settings.newNoise());
        world.setPlacementListener(this::placedRobotsChanged);
        if (settings.isLockstep()) {
            scheduler.hold();
        }
    }

    /**
     * A task, or an input applied between tasks, threw: a defect of the simulator's. The simulation goes
     * on, as a robot's world would, but the run is not to be trusted: the first failure is kept for the
     * run's status ({@link #getTaskFailure()}), and the log gets the whole stack for the report.
     */
    private void taskFailed(RuntimeException e) {
        if (taskFailure == null) {
            taskFailure = describe(e);
        }
        StringWriter trace = new StringWriter();
        e.printStackTrace(new PrintWriter(trace));
        log.logIt("X", "A simulation task failed; the simulation goes on, its run failed: " + trace.toString().stripTrailing());
    }

    /**
     * The sessions that have kept the interlock waiting for more than {@code seconds} of wall time
     * (none without the interlock).
     */
    public List<ClientSession> overdueSessions(double seconds) {
        if (interlock == null) {
            return List.of();
        }
        List<ClientSession> late = new ArrayList<>();
        for (Object client : interlock.overdue((long) (seconds * 1e9))) {
            late.add((ClientSession) client);
        }
        return late;
    }

    /** The first failure of a task of this simulation ({@link #taskFailed}), or null if none failed. */
    public String getTaskFailure() {
        return taskFailure;
    }

    private static String describe(Throwable t) {
        StackTraceElement[] trace = t.getStackTrace();
        return t + (trace.length > 0 ? " at " + trace[0] : "");
    }

    /** What each client attached from now on may make the server hold (default {@link ClientBudgets#DEFAULTS}). */
    public void setClientBudgets(ClientBudgets budgets) {
        clientBudgets = budgets;
    }

    public Scheduler getScheduler() {
        return scheduler;
    }

    public World getWorld() {
        return world;
    }

    /** The inputs waiting for the next boundary (a recording listens to them). */
    public InputQueue getInputs() {
        return inputs;
    }

    /** The seed of the model's random source. */
    public long getSeed() {
        return settings.randomSeed;
    }

    /** The results the clients reported of their own (a sweep's {@code result.NAME} columns). */
    public ReportedResults getReportedResults() {
        return reportedResults;
    }

    /** The names of the run's parameters its loaded clients asked for. */
    public AskedParameters getAskedParameters() {
        return askedParameters;
    }

    public RsLogInterface getLog() {
        return log;
    }

    /** The current simulation time, brought up to date with the wall clock. */
    public double getSimTime() {
        return scheduler.now();
    }

    /**
     * Attaches a client connection (after its handshake, if any): its requests become inputs of the
     * simulation and it receives its robot's events. For a {@link Link#READER} or
     * {@link Link#SHARED_READER} link start the connection's reading afterwards; for
     * {@link Link#DIRECT} connect the client to it first.
     */
    public ClientSession attach(RsConnection connection, String description, Link link) {
        connection.setLogger(log);
        ClientSession session = new ClientSession(clientNumbers.incrementAndGet(), description, connection, host);
        sessions.add(session);
        session.setDepartureListener(() -> departed(session));
        boolean interlocked = interlock != null && link != Link.DIRECT;
        Runnable afterRestart = link == Link.READER ? this::pump : () -> { };
        if (interlocked) {
            connection.addInterlock(interlock.forClient(session, afterRestart));
            session.setWriteGate(() -> interlock.sending(session));
        }
        if (link == Link.READER) {
            session.intake().setAfterSubmit(this::pump);
        }
        connection.setProtocolShutdownHandler(() -> {
            if (!interlocked) {
                session.intake().connectionClosed();
            } else if (interlock.leave(session, session.intake()::queueDeparture)) {
                afterRestart.run();
            }
        });
        return session;
    }

    /**
     * A client's departure has been applied (on the thread running tasks). In lockstep, a run whose
     * robots have all come and gone can never move again: the deserted action is told.
     */
    private void departed(ClientSession session) {
        sessions.remove(session);
        if (interlock != null) {
            interlock.forget(session);
        }
        if (settings.isLockstep() && robotsPlacedSoFar && waitingFor == 0 && placedRobots == 0 && sessions.isEmpty()) {
            whenDeserted.run();
        }
    }

    /** The sessions of the clients currently connected (read it from any thread). */
    public List<ClientSession> getSessions() {
        return sessions;
    }

    /**
     * Runs what is due on the calling thread for a moment, if no other thread is running tasks; the
     * dispatch loop takes over what remains. Transport threads call it after handing over messages.
     */
    public void pump() {
        scheduler.pump(PUMP_BUDGET_NANOS);
    }

    /** Starts the clock at simulation time 0 and runs tasks until {@link #shutdown()}. */
    public void run() {
        startClock();
        scheduler.runLoop();
    }

    /**
     * Runs tasks until {@link #shutdown()}, but with the clock stopped until {@link #startClock()}:
     * clients can connect and send their first requests, all applied at time 0, before anything moves.
     */
    public void runPaused() {
        scheduler.runLoop();
    }

    /** Starts the clock (at time 0). */
    public void startClock() {
        scheduler.begin();
    }

    /** Stops the scheduler; {@link #run()} returns. */
    public void shutdown() {
        scheduler.shutdown();
    }

    /**
     * Holds simulated time at 0 until {@code robots} robots are on the floor ({@code waitForClients});
     * work due at time 0 (their placements) still runs. Call before the clock starts.
     */
    public void waitForRobots(int robots) {
        if (robots > 0) {
            waitingFor = robots;
            scheduler.hold();
        }
    }

    /**
     * The number of robots on the floor changed. Time is held while clients are awaited and, in
     * lockstep, while no robot is on the floor (a world without robots has nothing to simulate, and a
     * lockstep clock would otherwise race to the next timed task).
     */
    private void placedRobotsChanged(int placed) {
        placedRobots = placed;
        robotsPlacedSoFar |= placed > 0;
        if (waitingFor > 0 && placed >= waitingFor) {
            waitingFor = 0;
        }
        boolean hold = waitingFor > 0 || (scheduler.isLockstep() && placed == 0);
        if (hold) {
            scheduler.hold();
        } else {
            scheduler.release();
        }
    }

    /**
     * Tells {@code action}, on the thread running tasks, when a lockstep run is deserted: the clients
     * that came have all left, no robot is on the floor, and {@code waitForClients} was met, so
     * simulated time stands still until somebody new connects (behavior.md section 3.5). The server
     * decides whether that ends the run.
     */
    public void whenDeserted(Runnable action) {
        whenDeserted = action;
    }

    /**
     * At {@code time}, after everything else due then, stops the scheduler and runs {@code action} (on
     * the thread running tasks): {@code maxSimulationTime}.
     */
    public void stopAt(double time, Runnable action) {
        scheduler.observeAt(time, t -> {
            scheduler.shutdown();
            action.run();
        });
    }

    /**
     * Runs {@code observer} at multiples of {@code period} of simulated time at which the world has
     * changed since it last ran, after every model task due then (pictures during a run).
     *
     * @return what stops the observations
     */
    public AutoCloseable observeChanges(double period, Task observer) {
        ChangeObserver o = new ChangeObserver(world, scheduler, period, observer);
        return o::close;
    }

    /**
     * A mouse press on the view at world point (x, y): every client with a robot that subscribed to
     * mouse clicks gets the event, stamped with the time the press is applied.
     */
    public void mouseClick(int button, int clickCount, double x, double y) {
        inputs.submit(new ViewInput(new ViewAction.MouseClick(button, clickCount, x, y), this));
    }

    /**
     * Pauses the run (the view's "Pause"): simulated time stands still between two tasks until
     * {@link #resume()}. Like the other clock controls, it changes when things happen on the wall
     * clock, never what happens at which simulated time.
     */
    public void pause() {
        scheduler.pause();
    }

    /** Ends a {@link #pause()}: time runs on from where it stood. */
    public void resume() {
        scheduler.unpause();
    }

    /** Whether the run is paused. */
    public boolean isPaused() {
        return scheduler.isPaused();
    }

    /** Simulated seconds per wall second now; infinity when as fast as possible. */
    public double getSpeed() {
        return scheduler.getSpeed();
    }

    /** Lets one modelling interval of simulated time pass (pausing first if the run goes on), then stands still. */
    public void stepOneInterval() {
        scheduler.step(settings.modelingInterval);
    }

    /**
     * From now on, {@code speed} simulated seconds per wall second, or as fast as possible for
     * infinity (as {@code simulationSpeed=max}, except that the run keeps its server's other settings).
     * A replay always runs as fast as possible.
     *
     * @throws IllegalArgumentException if the speed is not positive
     */
    public void setSpeed(double speed) {
        scheduler.setSpeed(speed);
        // A lockstep clock is held while no robot is on the floor; decide that anew on the task thread.
        scheduler.observeNow(t -> placedRobotsChanged(placedRobots));
    }

    /** Clears every paint trail (the view's "Remove Paint Trails"). */
    public void removePaintTrails() {
        inputs.submit(new ViewInput(new ViewAction.RemovePaintTrails(), this));
    }

    /** Told about every event the simulation produces for a client (an event log, run statistics). */
    @FunctionalInterface
    public interface EventListener {
        /**
         * On the thread running tasks, just before the event leaves for the client.
         *
         * @param delivered true if it is sent to the client; false for an event the model produced
         *                  that the client has not subscribed to
         */
        void event(ClientSession session, RsEvent event, boolean delivered);
    }

    /** Adds a listener for every event produced for the clients. */
    public void addEventListener(EventListener listener) {
        eventListeners.add(listener);
    }

    /** What the sessions work with. */
    private final class SessionHost implements ClientSession.Host {
        @Override
        public World world() {
            return world;
        }

        @Override
        public Scheduler scheduler() {
            return scheduler;
        }

        @Override
        public Heartbeats heartbeats() {
            return heartbeats;
        }

        @Override
        public RsLogInterface log() {
            return log;
        }

        @Override
        public ClientBudgets budgets() {
            return clientBudgets;
        }

        @Override
        public void submit(ClientSession session, Request request) {
            inputs.submit(new ClientInput(session, request));
        }

        @Override
        public void eventOut(ClientSession session, RsEvent event, boolean delivered) {
            for (EventListener l : eventListeners) {
                l.event(session, event, delivered);
            }
        }
    }
}
