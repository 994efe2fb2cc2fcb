package rp1.simulator.config;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalLong;
import java.util.Properties;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;

import rp1.simulator.noise.NoiseSettings;
import rp1.simulator.session.ClientBudgets;

/**
 * The server's settings, read from an RP1.ini-style properties file (behavior.md section 2.2, with
 * the user's guide's spellings {@code enableInterlock} and {@code dlcSetLogger} accepted as aliases)
 * plus the keys this implementation adds: {@code bindAddress}, {@code simulationSpeed=max},
 * {@code randomSeed}, {@code exitWhenClientsDone}, {@code maxSimulationTime}, {@code connectTimeout},
 * {@code clientQueueLimit}, {@code clientOutputBudget}, {@code clientTimeoutBudget},
 * {@code clientSubscriptionBudget}, {@code clientMessageBudget}, {@code snapshotFileName}, {@code snapshotInterval}, {@code robotsInteract},
 * {@code waitForClients}, {@code dlcDelivery}, {@code recordFileName}, {@code eventLogFileName},
 * {@code viewPort} and the {@code noise...} keys (docs/properties.md). Immutable; built
 * by {@link #from}, which validates every value and refuses a key it does not know.
 */
public final class ServerConfig {
    /**
     * Every key a server properties file may hold. A key read below must be declared here (reading an
     * undeclared one throws), and a key in a file that is not here is refused as a typo, with the
     * nearest of these suggested: so a new key is added by declaring it here, reading it in the
     * constructor and describing it in docs/properties.md.
     */
    static final Set<String> KEYS = Set.of(
            // RP1 0.60's keys, and the user's guide's spellings of two of them
            "port", "floorPlanFileName", "logFileName", "logToFile", "logToSystemOut", "logVerbose", "enableGUI",
            "enableNetworkClients", "simulationSpeed", "animationFrameRate", "modelingFrameRate", "dlcEnabled",
            "dlcName", "dlcSetIO", "dlcSetLog", "dlcSetLogger", "interlockEnabled", "enableInterlock",
            // this implementation's
            "bindAddress", "randomSeed", "exitWhenClientsDone", "maxSimulationTime", "connectTimeout", "interlockTimeout",
            "clientQueueLimit", "snapshotFileName", "snapshotInterval", "robotsInteract", "waitForClients",
            "dlcDelivery", "recordFileName", "eventLogFileName",
            "clientOutputBudget", "clientTimeoutBudget", "clientSubscriptionBudget", "clientMessageBudget",
            "viewPort",
            "noiseRangeSigma", "noiseRangeDropout", "noiseTargetRangeSigma", "noiseTargetBearingSigma",
            "noiseEncoderMiss", "noiseSlipDistanceSigma", "noiseSlipTurnSigma");

    /**
     * Keys an RP1 0.60 server file may hold that this server does not read, and why: accepted with a
     * warning. RP1 0.60's User's Guide has the server read {@code rossum.ini} as well, so files written
     * after it carry the client's keys.
     */
    static final Map<String, String> UNUSED_0_60_KEYS = Map.of(
            "hostName", "a client key (rossum.ini); the server listens on bindAddress and port");

    /** The prefix of the robot's parameters among the keys. */
    public static final String PARAMETER_PREFIX = "param.";

    /**
     * Prefixes under which any key is accepted: the robot's parameters ({@code param.NAME}), which
     * belong to the robot, not to the server.
     */
    static final List<String> KEY_FAMILIES = List.of(PARAMETER_PREFIX);

    private static final PropertyKeys DECLARED = new PropertyKeys(KEYS, UNUSED_0_60_KEYS, KEY_FAMILIES);

    public static final int DEFAULT_PORT = 7758;
    /** The original caps the animation rate at 32 frames per second. */
    public static final double MAX_ANIMATION_RATE = 32.0;

    public final int port;
    public final String bindAddress;
    public final String floorPlanFileName;
    public final String logFileName;
    public final boolean logToFile;
    public final boolean logToSystemOut;
    public final boolean logVerbose;
    public final boolean enableGUI;
    public final boolean enableNetworkClients;
    /** Simulated seconds per wall second; infinite when {@link #lockstep}. */
    public final double simulationSpeed;
    /** {@code simulationSpeed=max}: time jumps from task to task, never reading the wall clock. */
    public final boolean lockstep;
    public final double animationFrameRate;
    public final double modelingFrameRate;
    /** Seconds between motion evaluations: max(1 / modelingFrameRate, 0.001). */
    public final double modelingInterval;
    /** Seconds of wall time between animation frames: max(1 / animationFrameRate, 1/30). */
    public final double frameInterval;
    public final boolean dlcEnabled;
    /** Classes to load as in-process clients (the original loads at most one). */
    public final List<String> dlcNames;
    public final boolean dlcSetIO;
    public final boolean dlcSetLog;
    public final boolean interlockEnabled;
    /** Seed of the simulation's random source, if the properties give one. */
    public final OptionalLong randomSeed;
    public final boolean exitWhenClientsDone;
    /** Stop the server at this simulation time (infinite: never). */
    public final double maxSimulationTime;
    /** Seconds a new network connection may take to send CONNECT. */
    public final double connectTimeout;
    /**
     * Wall seconds a network client may keep the interlock waiting before it is disconnected; 0 (the
     * default): as long as it takes, as in RP1 0.60 (a robot held at a debugger's breakpoint).
     */
    public final double interlockTimeout;
    /** Events that may wait for a slow client before it is disconnected. */
    public final int clientQueueLimit;
    /**
     * What one client may make the server hold, in bytes ({@code clientOutputBudget},
     * {@code clientTimeoutBudget}, {@code clientSubscriptionBudget}, {@code clientMessageBudget}).
     */
    public final ClientBudgets clientBudgets;
    /** Where to write pictures of the world, or null. */
    public final String snapshotFileName;
    /** Simulated seconds between pictures (0: only at exit). */
    public final double snapshotInterval;
    /** Whether robots collide with, sense and block the placement of one another (RP1 0.60: no). */
    public final boolean robotsInteract;
    /**
     * Robots to be placed before simulated time may run: by default 1 at {@code simulationSpeed=max} with
     * network clients and no loaded client (a lockstep clock would otherwise run ahead of them), else 0.
     */
    public final int waitForClients;
    /** How loaded clients get their events ({@code dlcDelivery}). */
    public enum Delivery {
        /** Directly where the client allows it, else through pipes. */
        AUTO,
        /** Directly; a client that does not allow it fails start-up. */
        DIRECT,
        /** Through pipes, as in RP1 0.60. */
        PIPES
    }

    /** How loaded clients get their events. */
    public final Delivery dlcDelivery;
    /** Where to write a recording of the run, to replay it (docs/recording.md), or null. */
    public final String recordFileName;
    /** Where to write every event sent to a client, one line each (docs/recording.md), or null. */
    public final String eventLogFileName;
    /** The port a browser watches the run on ({@code viewPort}, docs/properties.md); 0: no live view. */
    public final int viewPort;
    /**
     * The robot's parameters: every {@code param.NAME} key, by NAME, with its value's first word.
     * Loaded clients read them with {@code RsClient.getRunParameter}; a sweep varies them.
     */
    public final SortedMap<String, String> parameters;
    /** How noisy sensors and motion are (the {@code noise...} keys); {@link NoiseSettings#OFF} by default. */
    public final NoiseSettings noise;
    /** The properties as given (values unparsed), sorted by key: a recording keeps them. */
    public final SortedMap<String, String> given;
    /** What was accepted but is worth saying (a key RP1 0.60 had that this server ignores), one line each. */
    public final List<String> warnings;

    private ServerConfig(PropertyReader r, String planOverride, boolean strictKeys) throws ConfigException {
        warnings = List.copyOf(DECLARED.check(r, strictKeys));
        port = r.integer("port", DEFAULT_PORT, 1, 65535);
        bindAddress = orDefault(r.string("bindAddress"), "127.0.0.1");
        floorPlanFileName = planOverride != null ? planOverride : r.string("floorPlanFileName");
        logFileName = r.string("logFileName");
        logToFile = r.bool(false, "logToFile");
        logToSystemOut = r.bool(false, "logToSystemOut");
        logVerbose = r.bool(false, "logVerbose");
        enableGUI = r.bool(true, "enableGUI");
        enableNetworkClients = r.bool(true, "enableNetworkClients");
        lockstep = "max".equals(r.string("simulationSpeed"));
        simulationSpeed = lockstep ? Double.POSITIVE_INFINITY : r.real("simulationSpeed", 1.0, 0.001, 1000.0);
        animationFrameRate = Math.min(MAX_ANIMATION_RATE, r.real("animationFrameRate", 20.0, 1.0e-3, Double.MAX_VALUE));
        modelingFrameRate = Math.max(animationFrameRate, r.real("modelingFrameRate", 20.0, 1.0e-3, Double.MAX_VALUE));
        modelingInterval = Math.max(1.0 / modelingFrameRate, 0.001);
        frameInterval = Math.max(1.0 / animationFrameRate, 1.0 / 30.0);
        dlcEnabled = r.bool(false, "dlcEnabled");
        dlcNames = splitNames(r.string("dlcName"));
        dlcSetIO = r.bool(true, "dlcSetIO");
        dlcSetLog = r.bool(true, "dlcSetLog", "dlcSetLogger");
        interlockEnabled = r.bool(false, "interlockEnabled", "enableInterlock");
        String seed = r.string("randomSeed");
        randomSeed = seed == null ? OptionalLong.empty() : OptionalLong.of(r.longValue("randomSeed", 0L));
        exitWhenClientsDone = r.bool(false, "exitWhenClientsDone");
        maxSimulationTime = r.real("maxSimulationTime", Double.POSITIVE_INFINITY, 0.0, Double.POSITIVE_INFINITY);
        connectTimeout = r.real("connectTimeout", 10.0, 0.001, 86400.0);
        interlockTimeout = r.real("interlockTimeout", 0.0, 0.0, 86400.0);
        clientQueueLimit = r.integer("clientQueueLimit", 10000, 16, Integer.MAX_VALUE);
        ClientBudgets budgets = ClientBudgets.DEFAULTS;
        clientBudgets = new ClientBudgets(
                r.integer("clientOutputBudget", budgets.output, 64 << 10, Integer.MAX_VALUE),
                r.integer("clientTimeoutBudget", budgets.timeouts, 4 << 10, Integer.MAX_VALUE),
                r.integer("clientSubscriptionBudget", budgets.subscriptions, 4 << 10, Integer.MAX_VALUE),
                r.integer("clientMessageBudget", budgets.message, 64 << 10, budgets.message));
        snapshotFileName = r.string("snapshotFileName");
        snapshotInterval = r.real("snapshotInterval", 0.0, 0.0, Double.POSITIVE_INFINITY);
        robotsInteract = r.bool(true, "robotsInteract");
        waitForClients = r.integer("waitForClients", lockstep && enableNetworkClients && !dlcEnabled ? 1 : 0, 0,
                Integer.MAX_VALUE);
        dlcDelivery = Delivery.valueOf(r.choice("dlcDelivery", "auto", "auto", "direct", "pipes").toUpperCase(Locale.ROOT));
        recordFileName = r.string("recordFileName");
        eventLogFileName = r.string("eventLogFileName");
        viewPort = r.integer("viewPort", 0, 0, 65535);
        noise = readNoise(r);
        given = r.given();
        parameters = parameters(r);
        checkConsistency(r);
    }

    private void checkConsistency(PropertyReader r) throws ConfigException {
        String where = r.source() + ": ";
        if (logToFile && logFileName == null) {
            throw new ConfigException(where + "logToFile=true, but logFileName is missing");
        }
        if (dlcEnabled && dlcNames.isEmpty()) {
            throw new ConfigException(where + "dlcEnabled=true, but no class name is given in dlcName");
        }
        if (dlcEnabled && !dlcSetIO && !enableNetworkClients) {
            throw new ConfigException(where + "dlcSetIO=false makes the loaded client connect over the network, "
                    + "but enableNetworkClients=false");
        }
        if (floorPlanFileName == null) {
            throw new ConfigException(where + "the floor plan is missing: give floorPlanFileName or -f PLAN");
        }
        int loaded = dlcEnabled ? dlcNames.size() : 0;
        if (!enableNetworkClients && waitForClients > loaded) {
            String clients = loaded == 0 ? "no client is" : "only " + loaded + (loaded == 1 ? " client is" : " clients are");
            throw new ConfigException(where + "waitForClients=" + waitForClients + " can never be met: network clients "
                    + "are disabled (enableNetworkClients=false) and " + clients + " loaded (dlcName), each with one robot");
        }
        if (lockstep && !interlockEnabled) {
            throw new ConfigException(where + "simulationSpeed=max needs interlockEnabled=true "
                    + "(without the interlock nothing would hold simulated time back for the clients)");
        }
        checkOutputsApart(where);
    }

    /**
     * The files a run writes are different files: an event log named as the recording replaced it
     * (the recording was lost), a log named as the recording overwrote it without a word.
     */
    private void checkOutputsApart(String where) throws ConfigException {
        Map<Path, String> outputs = new LinkedHashMap<>();
        String[][] named = {{"recordFileName", recordFileName}, {"eventLogFileName", eventLogFileName},
            {"logFileName", logToFile ? logFileName : null}, {"snapshotFileName", snapshotFileName}};
        for (String[] output : named) {
            if (output[1] == null) {
                continue;
            }
            Path file;
            try {
                file = Paths.get(output[1]).toAbsolutePath().normalize();
            } catch (InvalidPathException e) {
                continue; // said where the file is opened
            }
            String other = outputs.putIfAbsent(file, output[0]);
            if (other != null) {
                throw new ConfigException(where + other + " and " + output[0] + " name the same file, " + output[1]
                        + ": each of the run's outputs needs a file of its own");
            }
        }
    }

    private static NoiseSettings readNoise(PropertyReader r) throws ConfigException {
        double big = Double.MAX_VALUE;
        return new NoiseSettings(r.real("noiseRangeSigma", 0.0, 0.0, big), r.real("noiseRangeDropout", 0.0, 0.0, 1.0),
                r.real("noiseTargetRangeSigma", 0.0, 0.0, big),
                Math.toRadians(r.real("noiseTargetBearingSigma", 0.0, 0.0, 360.0)),
                r.real("noiseEncoderMiss", 0.0, 0.0, 1.0), r.real("noiseSlipDistanceSigma", 0.0, 0.0, 10.0),
                r.real("noiseSlipTurnSigma", 0.0, 0.0, 10.0));
    }

    /**
     * Validates and builds a configuration.
     *
     * @param table        the properties
     * @param source       where they came from, for error messages
     * @param planOverride a floor plan given on the command line ({@code -f}), or null
     */
    public static ServerConfig from(Properties table, String source, String planOverride) throws ConfigException {
        return new ServerConfig(new PropertyReader(table, source, DECLARED), planOverride, true);
    }

    /**
     * Like {@link #from}, but a key this version does not know is only a warning: for the properties a
     * recording kept, which an older version accepted (it ignored unknown keys) and which must replay.
     */
    public static ServerConfig fromRecorded(Properties table, String source) throws ConfigException {
        return new ServerConfig(new PropertyReader(table, source, DECLARED), null, false);
    }

    /**
     * The {@code param.NAME} keys: accepted whatever NAME is, since they belong to the robot, not to
     * the server (docs/properties.md).
     */
    private static SortedMap<String, String> parameters(PropertyReader r) throws ConfigException {
        SortedMap<String, String> parameters = new TreeMap<>();
        for (String key : r.given().keySet()) {
            if (key.startsWith(PARAMETER_PREFIX)) {
                String name = key.substring(PARAMETER_PREFIX.length());
                if (name.isEmpty()) {
                    throw r.error(key, r.given().get(key), "a parameter needs a name after " + PARAMETER_PREFIX);
                }
                String value = r.string(key);
                parameters.put(name, value == null ? "" : value);
            }
        }
        return Collections.unmodifiableSortedMap(parameters);
    }

    /** Whether {@code key} is a parameter of the robot ({@code param.NAME}), which any properties may hold. */
    public static boolean isParameter(String key) {
        return key.startsWith(PARAMETER_PREFIX) && key.length() > PARAMETER_PREFIX.length();
    }

    private static String orDefault(String v, String fallback) {
        return v == null ? fallback : v;
    }

    private static List<String> splitNames(String v) {
        if (v == null) {
            return Collections.emptyList();
        }
        List<String> names = new ArrayList<>();
        for (String s : Arrays.asList(v.split(","))) {
            if (!s.trim().isEmpty()) {
                names.add(s.trim());
            }
        }
        return Collections.unmodifiableList(names);
    }
}
