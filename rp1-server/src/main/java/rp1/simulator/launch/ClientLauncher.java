package rp1.simulator.launch;

import java.io.IOException;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import rp1.rossum.RsClient;
import rp1.rossum.RsProperties;
import rp1.simulator.net.InProcessClient;
import rp1.simulator.Simulation;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.net.ClientConnection;
import rp1.simulator.net.ClientRegistry;
import rp1.simulator.net.OutboundQueue;
import rp1.simulator.net.Transport;

/**
 * Launches the dynamically loaded clients named in {@code dlcName} (docs/behavior.md section 3.4;
 * several names may be given, comma-separated). Calls, in the original's order: constructor,
 * {@code setInputOutputStreams} (with {@code dlcSetIO}: in-process pipes, no handshake),
 * {@code setLogger} (with {@code dlcSetLog}: the server's log), then {@code initialize()} and
 * {@code run()} on a thread per client. An {@code RsClient} is also told the run it is part of
 * ({@code setRunContext}): the {@code param.NAME} properties, the seed, and where its results go.
 *
 * <p>The clients are connected, and so numbered, in the order {@code dlcName} lists them, and started
 * one at a time in that order: a client's {@code initialize()} begins only once the one before has
 * returned from its own and the server has read what it sent meanwhile (or after
 * {@code connectTimeout} seconds, with a log line). So bodies, part ids and first requests reach the
 * simulation in the listed order whatever the threads do, and a run with several loaded robots is
 * the same for the same seed.
 *
 * <p>An {@code RsClient} that keeps the library's event loop is instead connected directly
 * ({@code dlcDelivery=auto} or {@code direct}): the simulation calls its handlers on the thread that
 * runs the tasks and its requests go straight to its session, with no pipes and no thread once
 * {@code initialize()} has returned; it is done when its session ends. {@code dlcDelivery=pipes}
 * keeps every loaded client on pipes.
 *
 * <p>Without {@code dlcSetIO} the client connects over TCP itself; an {@code RsClient} is given the
 * server's actual address and port in its {@code rsProperties}, any other {@code RsRunnable} has to
 * find them on its own.
 */
final class ClientLauncher implements LoadedClient.Listener {
    /** How long a thread that has run nothing yet is given to show whose it is, milliseconds. */
    private static final long NOT_YET_RUNNING_MILLIS = 50;

    /** What the server does when clients fail or finish. */
    interface Outcome {
        /** A client's {@code initialize()} threw; {@code failure} says so as the log did. */
        void clientFailed(String failure);

        /** Every client's thread has ended; {@code firstFailure} is the first that failed, or null. */
        void allFinished(String firstFailure);
    }

    private final List<LoadedClient> clients;
    /**
     * The threads that run the robots' code: the clients' own threads, the simulation's (which calls
     * the handlers of clients connected directly), and every thread those start (a new thread joins
     * its starter's group), so that the threads a robot leaves behind can be found when the run ends,
     * whether it started them from {@code initialize()}, {@code run()} or a handler. Let go by
     * {@link #releaseThreads}.
     */
    private final ThreadGroup robots = new ThreadGroup("robots");
    private final ServerConfig config;
    private final ServerLog log;
    private final AtomicInteger running;
    private volatile Outcome outcome;
    /** Set when the run stops: the clients not started by then never are. */
    private volatile boolean calledOff;

    private ClientLauncher(List<LoadedClient> clients, ServerConfig config, ServerLog log) {
        this.clients = clients;
        this.config = config;
        this.log = log;
        this.running = new AtomicInteger(clients.size());
    }

    /**
     * Loads and instantiates every client class the configuration names (none unless
     * {@code dlcEnabled}).
     *
     * @throws StartupException if a class cannot be used; nothing is started
     */
    static ClientLauncher create(ServerConfig config, ServerLog log, ClassLoader loader) throws StartupException {
        List<LoadedClient> loaded = new ArrayList<>();
        if (config.dlcEnabled) {
            for (String name : config.dlcNames) {
                log.log("Loading class for client: \"" + name + "\"");
                LoadedClient c = LoadedClient.create(name, loader);
                String whyNot = c.whyNotDirect();
                if (whyNot != null && config.dlcSetIO && config.dlcDelivery == ServerConfig.Delivery.DIRECT) {
                    throw new StartupException("dlcDelivery=direct, but client class " + name + " cannot be called directly: "
                            + whyNot + " (use dlcDelivery=auto or pipes)");
                }
                loaded.add(c);
            }
        }
        return new ClientLauncher(Collections.unmodifiableList(loaded), config, log);
    }

    boolean isEmpty() {
        return clients.isEmpty();
    }

    /** The group the simulation's thread belongs in: the one of the robots' threads. */
    ThreadGroup robotThreads() {
        return robots;
    }

    /**
     * The run is stopping: the clients still waiting their turn are never started (the launcher goes
     * on through them at once), and their threads, where prepared, end.
     */
    void callOffWaiting() {
        calledOff = true;
        for (LoadedClient c : clients) {
            c.callOff();
        }
    }

    /** The clients' threads started so far (ended or not). Threads a client starts itself are not among them. */
    List<Thread> threads() {
        List<Thread> started = new ArrayList<>();
        for (LoadedClient c : clients) {
            if (c.thread() != null) {
                started.add(c.thread());
            }
        }
        return started;
    }

    /**
     * The live threads the clients started (in {@code initialize()}, {@code run()} or a handler, and the
     * threads those started) that are running code of the class path, a robot's: not the clients'
     * threads themselves, not the simulation's ({@code simulation}), not the caller's, and not threads
     * idle in the JDK's own code. Those may be the JDK's, serving every run in the process (a robot's first
     * parallel stream starts the common fork-join pool's workers, its first delayed future the JDK's
     * scheduler), and ending them would break the runs after; an idle pool thread of a robot's own
     * costs only memory.
     */
    List<Thread> startedByClients(Thread simulation) {
        Thread[] all = new Thread[robots.activeCount() + 8];
        int n = robots.enumerate(all, true);
        List<Thread> own = threads();
        List<Thread> strays = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Thread t = all[i];
            if (t.isAlive() && t != Thread.currentThread() && t != simulation && !own.contains(t)
                    && !(t instanceof ForkJoinWorkerThread)
                    && runsClassPathCode(t)) {
                strays.add(t);
            }
        }
        return strays;
    }

    /**
     * Lets the clients' thread group go once no thread is left in it. On Java 17 a group stays listed
     * in its parent until it is destroyed, and a sweep makes one per run; a group with a thread still
     * in it (one that would not end) stays, as does every group on a Java that no longer destroys them.
     */
    @SuppressWarnings("removal")
    void releaseThreads() {
        try {
            robots.destroy();
        } catch (RuntimeException stillInUse) {
            // See above: nothing else to do.
        }
    }

    /**
     * Whether a frame of {@code t}'s stack is of a class on the class path (in no named module). A thread
     * a robot has just started, on a busy machine, may not have been given a processor by the time its
     * run ends and has no frame yet to tell whose it is: it is given a moment to show one, and counted
     * as the robot's if it still shows none.
     */
    private static boolean runsClassPathCode(Thread t) {
        StackTraceElement[] stack = t.getStackTrace();
        for (long waited = 0; stack.length <= 1 && t.isAlive(); waited++) {
            if (waited == NOT_YET_RUNNING_MILLIS) {
                return true;
            }
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return true;
            }
            stack = t.getStackTrace();
        }
        for (StackTraceElement e : stack) {
            if (e.getModuleName() == null && !e.isNativeMethod()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Connects every client to {@code simulation}, in order, then starts their threads one after the
     * other on a thread {@code helpers} gives (see the class comment), and then runs {@code whenStarted} on it:
     * once every client's {@code initialize()} has returned and the server has dealt with the requests
     * an in-process one sent meanwhile, or its {@code connectTimeout} has passed. A lockstep simulation
     * starts its clock then, so a run's first requests are all stamped at time 0, in the order of
     * {@code dlcName}, and the same seed gives the same run.
     *
     * @param port the port of the server's listener, for clients that connect over TCP (-1 if none)
     */
    void launch(Simulation simulation, ClientRegistry registry, int port, Outcome whenDone, HelperThreads helpers,
                Runnable whenStarted)
            throws IOException {
        outcome = whenDone;
        for (LoadedClient c : clients) {
            int session = LoadedRunContext.NO_SESSION;
            if (config.dlcSetIO && config.dlcDelivery != ServerConfig.Delivery.PIPES && c.whyNotDirect() == null) {
                session = connectDirect(c, simulation, registry);
            } else if (config.dlcSetIO) {
                session = connectInProcess(c, simulation, registry);
            } else {
                pointAtServer(c, port);
                if (config.dlcSetLog) {
                    c.client.setLogger(log);
                }
            }
            if (c.client instanceof RsClient rs) {
                rs.setRunContext(new LoadedRunContext(config.parameters, simulation.getAskedParameters(),
                        simulation.getSeed(), simulation.getReportedResults(), session));
            }
        }
        helpers.start("dlc start", true, () -> startInOrder(whenStarted));
    }

    /**
     * Starts each client once the one before is ready, each given at most {@code connectTimeout}, then
     * runs {@code whenStarted} (not if the server is stopping). The next client's thread is prepared
     * while a client initializes; the client itself starts only when its turn comes.
     */
    private void startInOrder(Runnable whenStarted) {
        try {
            for (int i = 0; i < clients.size(); i++) {
                if (calledOff) {
                    return;
                }
                LoadedClient c = clients.get(i);
                log.log("Launching thread for client: \"" + c.className + "\"");
                c.start(log, this, robots);
                if (i + 1 < clients.size()) {
                    clients.get(i + 1).prepare(log, this, robots);
                }
                long deadline = System.nanoTime() + (long) (config.connectTimeout * TimeUnit.SECONDS.toNanos(1));
                if (!c.awaitReady(deadline)) {
                    log.log("client " + c.className + ": initialize() has not finished after " + config.connectTimeout
                            + " s; going on without waiting for it");
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        if (!calledOff) {
            whenStarted.run();
        }
    }

    /** Connects the client through pipes; returns its session number. */
    private int connectInProcess(LoadedClient c, Simulation simulation, ClientRegistry registry) {
        String description = "client " + registry.nextNumber() + " (in-process " + c.className + ")";
        ClientConnection connection = new ClientConnection(description);
        registry.add(connection);
        InProcessClient link = new InProcessClient(simulation, c.client, description, config.dlcSetLog, connection,
                pipe -> OutboundQueue.start(Transport.of(pipe), config.clientQueueLimit, config.clientBudgets.output,
                        "writer " + description, connection::close));
        c.setLink(link);
        log.log(description + " connected");
        return link.session().getNumber();
    }

    /**
     * The client's handlers are called by the simulation itself, its requests go straight to its
     * session: no pipes, no event loop, no thread once {@code initialize()} has returned. Returns its
     * session number.
     */
    private int connectDirect(LoadedClient c, Simulation simulation, ClientRegistry registry) {
        String description = "client " + registry.nextNumber() + " (in-process " + c.className + ", direct)";
        ClientConnection connection = new ClientConnection(description);
        registry.add(connection);
        int session = simulation.attach(connection, description, Simulation.Link.DIRECT).getNumber();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        connection.addEndListener(() -> c.sessionEnded(log, this, failure.get()));
        connection.connectDirect((RsClient) c.client, failure::set);
        c.setDirect(connection);
        if (config.dlcSetLog) {
            c.client.setLogger(log);
        }
        log.log(description + " connected");
        return session;
    }

    private void pointAtServer(LoadedClient c, int port) throws IOException {
        if (!(c.client instanceof RsClient)) {
            return;
        }
        InetAddress bound = InetAddress.getByName(config.bindAddress);
        RsProperties p = new RsProperties();
        p.hostName = bound.isAnyLocalAddress() ? InetAddress.getLoopbackAddress().getHostAddress() : bound.getHostAddress();
        p.port = port;
        ((RsClient) c.client).rsProperties = p;
    }

    @Override
    public void initializeFailed(LoadedClient client) {
        outcome.clientFailed(client.failure());
    }

    @Override
    public void finished(LoadedClient client) {
        if (running.decrementAndGet() == 0) {
            outcome.allFinished(firstFailure());
        }
    }

    /** The failure of the first loaded client (in {@code dlcName} order) that failed so far, or null. */
    String firstFailure() {
        for (LoadedClient c : clients) {
            if (c.failure() != null) {
                return c.failure();
            }
        }
        return null;
    }
}
