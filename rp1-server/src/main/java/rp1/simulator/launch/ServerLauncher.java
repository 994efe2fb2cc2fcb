package rp1.simulator.launch;

import java.io.IOException;
import java.net.BindException;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SortedMap;
import java.util.TreeMap;

import rp1.io.IoFailures;
import rp1.planparser.ParsedPlans;
import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ResourceLocator;
import rp1.simulator.config.ServerArguments;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.net.ClientListener;
import rp1.simulator.net.ClientRegistry;
import rp1.simulator.net.WarmUp;
import rp1.simulator.record.Recorder;
import rp1.simulator.record.RunRecords;

/**
 * Starts a server from its command line ({@code -p PROPERTIES}, {@code -f PLAN}, {@code --port N},
 * {@code -cp PATH}) the way
 * {@code rp1.Server} does, but returns a handle instead of owning the process, so tests run servers
 * in-process on free ports (behavior.md sections 2 and 3.1).
 *
 * <p>Everything that can be checked before anything runs is checked first: command line, properties,
 * log file, floor plan, client classes, the listening port. Any failure there is one
 * {@link StartupException} with a one-line message (also written to the log if it is open), and
 * nothing is left running.
 */
public final class ServerLauncher {
    private ServerLauncher() {
    }

    /** {@link #start(String[], Path, LaunchOptions)} with the default options. */
    public static RunningServer start(String[] args, Path workingDirectory) throws StartupException {
        return start(args, workingDirectory, LaunchOptions.defaults());
    }

    /**
     * Starts a server.
     *
     * @param args             the command line ({@link ServerArguments})
     * @param workingDirectory where {@code -p}, the floor plan, {@code -cp}'s entries and the log file are
     *                         looked for first
     * @param options          a port override (before {@code --port} and the properties' port), the view
     *                         and the clients' class loader (to which {@code -cp} adds)
     * @throws StartupException if the server cannot start; nothing is left running
     */
    public static RunningServer start(String[] args, Path workingDirectory, LaunchOptions options)
            throws StartupException {
        ServerArguments arguments = arguments(args);
        ClassLoader base = options.loader != null ? options.loader : classLoader();
        ClassLoader loader = ClientClassPath.loader(ClientClassPath.resolve(arguments.classPath, workingDirectory), base);
        ResourceLocator locator = new ResourceLocator(workingDirectory, loader);
        ServerConfig config = configure(arguments, locator);
        ServerLog log = openLog(config, workingDirectory);
        ClientListener listener = null;
        ClientLauncher launcher = null;
        RunRecords records = RunRecords.none();
        RunningServer.Parts parts;
        try {
            log.important("STARTING SIMULATOR SESSION");
            config.warnings.forEach(log::important);
            ResourceLocator.Found planText = readPlan(config, locator, log);
            long seed = config.randomSeed.orElse(System.nanoTime());
            Simulation simulation = simulate(config, planText, options.plans, seed, log);
            records = keepRecords(config, workingDirectory, simulation, planText, seed, log);
            launcher = ClientLauncher.create(config, log, loader);
            ClientRegistry registry = new ClientRegistry(log);
            int port = options.port.orElse(arguments.port.orElse(config.port));
            listener = listen(config, port, simulation, planText, registry, log);
            parts = new RunningServer.Parts(config, log, simulation, registry, listener, launcher, options.view, records,
                    options.helpers);
        } catch (StartupException | RuntimeException e) {
            if (listener != null) {
                listener.close();
            }
            if (launcher != null) {
                launcher.releaseThreads();
            }
            records.close();
            String message = e instanceof StartupException ? e.getMessage() : LoadedClient.describe(e);
            log.important("Fatal error: " + message);
            log.close();
            throw e;
        }
        return RunningServer.begin(parts);
    }

    private static ClassLoader classLoader() {
        ClassLoader context = Thread.currentThread().getContextClassLoader();
        return context != null ? context : ServerLauncher.class.getClassLoader();
    }

    private static ServerArguments arguments(String[] args) throws StartupException {
        try {
            return ServerArguments.parse(args);
        } catch (ConfigException e) {
            throw new StartupException(e.getMessage());
        }
    }

    /** Reads the properties the command line names; every value is validated. */
    private static ServerConfig configure(ServerArguments arguments, ResourceLocator locator) throws StartupException {
        try {
            ResourceLocator.Found found = locator.properties(arguments.propertiesName);
            ServerConfig config = ServerConfig.from(ResourceLocator.parseProperties(found), found.location,
                    arguments.planName);
            if (config.exitWhenClientsDone && !config.dlcEnabled) {
                throw new ConfigException(found.location + ": exitWhenClientsDone=true, but no client is loaded "
                        + "(dlcEnabled is false): the server would never exit");
            }
            return config;
        } catch (ConfigException e) {
            throw new StartupException(e.getMessage());
        }
    }

    private static ServerLog openLog(ServerConfig config, Path workingDirectory) throws StartupException {
        String file = config.logToFile ? workingDirectory.resolve(config.logFileName).toString() : null;
        try {
            return ServerLog.open(file, config.logToSystemOut, config.logVerbose);
        } catch (IOException e) {
            throw new StartupException("cannot create the log file " + file + " (logFileName): " + IoFailures.why(e));
        }
    }

    private static ResourceLocator.Found readPlan(ServerConfig config, ResourceLocator locator, ServerLog log)
            throws StartupException {
        try {
            ResourceLocator.Found text = locator.plan(config.floorPlanFileName);
            log.log("Loading floor plan from " + text.location);
            return text;
        } catch (ConfigException e) {
            throw new StartupException(e.getMessage());
        }
    }

    /** Parses the floor plan and creates the simulation, seeded (and the seed logged, to repeat the run). */
    private static Simulation simulate(ServerConfig config, ResourceLocator.Found text, ParsedPlans plans, long seed,
                                       ServerLog log) throws StartupException {
        RsPlan plan = parse(config, text, plans);
        log.log("randomSeed=" + seed + (config.randomSeed.isPresent() ? "" : "; set it to repeat this run"));
        Simulation simulation = new Simulation(plan, SimulationSettings.of(config, seed), log);
        simulation.setClientBudgets(config.clientBudgets);
        log.setSimTime(simulation.getScheduler()::recordedTime);
        if (config.waitForClients > 0) {
            log.log("Simulated time waits until " + config.waitForClients + " robot" + (config.waitForClients == 1 ? " is" : "s are")
                    + " placed (waitForClients)");
            simulation.waitForRobots(config.waitForClients);
        }
        return simulation;
    }

    /** The plan {@code text} holds: parsed here, or a copy of the one {@code plans} (when not null) parsed before. */
    private static RsPlan parse(ServerConfig config, ResourceLocator.Found text, ParsedPlans plans) throws StartupException {
        try {
            return plans != null ? plans.copyOf(text.text, text.location) : RsPlanParser.parse(text.reader(), text.location);
        } catch (RsParsingException e) {
            throw new StartupException(e.getMessage());
        } catch (IOException e) {
            throw new StartupException("cannot read the floor plan " + config.floorPlanFileName + ": " + IoFailures.why(e));
        }
    }

    /**
     * Opens the recording and the event log if the properties ask for them. The recording keeps the
     * properties as they took effect: the floor plan given with -f, the seed chosen when none was set.
     */
    private static RunRecords keepRecords(ServerConfig config, Path workingDirectory, Simulation simulation,
                                          ResourceLocator.Found planText, long seed, ServerLog log)
            throws StartupException {
        SortedMap<String, String> properties = new TreeMap<>(config.given);
        properties.put("floorPlanFileName", config.floorPlanFileName);
        properties.put("randomSeed", Long.toString(seed));
        Recorder.Header header = new Recorder.Header(properties, planText.location, planText.text, seed);
        try {
            RunRecords records = RunRecords.open(simulation, header, resolve(workingDirectory, config.recordFileName),
                    resolve(workingDirectory, config.eventLogFileName), log);
            if (config.recordFileName != null) {
                log.log("Recording the run in " + config.recordFileName + " (replay it with rp1.Replay)");
            }
            if (config.eventLogFileName != null) {
                log.log("Writing every event sent to " + config.eventLogFileName);
            }
            return records;
        } catch (IOException e) {
            throw new StartupException(e.getMessage());
        }
    }

    private static Path resolve(Path workingDirectory, String file) {
        return file == null ? null : workingDirectory.resolve(file);
    }

    private static ClientListener listen(ServerConfig config, int port, Simulation simulation,
                                         ResourceLocator.Found planText, ClientRegistry registry, ServerLog log)
            throws StartupException {
        if (!config.enableNetworkClients) {
            log.log("Network client connections disabled (in response to configuration option)");
            return null;
        }
        WarmUp.run(parse(config, planText, null));
        try {
            ClientListener listener = ClientListener.bind(config.bindAddress, port, simulation, registry, log,
                    new ClientListener.Settings(config.connectTimeout, config.clientQueueLimit, config.clientBudgets)
                            .withInterlockTimeout(config.interlockTimeout));
            log.log("Socket ready: " + config.bindAddress + ":" + listener.getPort());
            return listener;
        } catch (IOException e) {
            // The likely cause, by what failed: the port taken, or an address this machine does not have.
            String hint = e instanceof BindException ? " (is another simulator running? choose another port with the port key)"
                    : e instanceof UnknownHostException ? " (bindAddress names no address of this machine)" : "";
            throw new StartupException(String.format(Locale.ROOT, "cannot listen on %s:%d: %s%s",
                    config.bindAddress, port, e.getMessage(), hint));
        }
    }
}
