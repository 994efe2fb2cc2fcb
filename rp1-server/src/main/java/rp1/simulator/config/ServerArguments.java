package rp1.simulator.config;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.OptionalInt;

/**
 * The server's command line: {@code -p PROPERTIES} and {@code -f PLAN}, as RP1 0.60 reads it (the
 * last occurrence of a flag wins), {@code --port N}, {@code --headless}, {@code -cp PATH} and
 * {@code -h}/{@code --help}. Anything else is refused with the usage (RP1 0.60 ignored it, so a
 * mistyped option went unnoticed).
 */
public final class ServerArguments {
    /** What the command line may hold. */
    public static final String USAGE = String.join("\n",
            "usage: java rp1.Server [-p PROPERTIES] [-f FLOORPLAN] [--port N] [--headless] [-cp PATH]",
            "  -p PROPERTIES    properties file: a path, or Properties/NAME on the class path (default Properties/RP1.ini)",
            "  -f FLOORPLAN     floor plan to use instead of the properties' floorPlanFileName",
            "  --port N         listen on port N (1 to 65535) instead of the properties' port",
            "  --headless       no window, whatever enableGUI says",
            "  -cp, --classpath PATH",
            "                   where the classes named in dlcName are looked for, besides the simulator's own:",
            "                   folders and jars separated by '" + File.pathSeparator + "'",
            "  -h, --help       print this and exit",
            "Files are relative to the working directory.");

    /** The properties file named with -p, or null for the default RP1.ini. */
    public final String propertiesName;
    /** The floor plan named with -f, or null to use the properties' floorPlanFileName. */
    public final String planName;
    /** Whether the usage was asked for ({@code -h}, {@code --help}). */
    public final boolean help;
    /** The port given with --port, replacing the properties' one. */
    public final OptionalInt port;
    /** Whether --headless was given. */
    public final boolean headless;
    /** The entries of every -cp given, in order, as written. */
    public final List<String> classPath;

    private ServerArguments(String propertiesName, String planName, boolean help, OptionalInt port, boolean headless,
                            List<String> classPath) {
        this.propertiesName = propertiesName;
        this.planName = planName;
        this.help = help;
        this.port = port;
        this.headless = headless;
        this.classPath = Collections.unmodifiableList(classPath);
    }

    /** Parses the arguments; a flag without a value, or an argument it does not know, is an error. */
    public static ServerArguments parse(String[] args) throws ConfigException {
        String p = null;
        String f = null;
        boolean help = false;
        OptionalInt port = OptionalInt.empty();
        boolean headless = false;
        List<String> classPath = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String flag = args[i];
            switch (flag) {
                case "-p" -> p = value(args, ++i, "Missing specification for -p option (a properties file)");
                case "-f" -> f = value(args, ++i, "Missing specification for -f option (a floor plan)");
                case "--port" -> port = OptionalInt.of(port(value(args, ++i, "--port needs a port number")));
                case "--headless" -> headless = true;
                case "-cp", "-classpath", "--classpath" -> classPath.addAll(entries(value(args, ++i,
                        flag + " needs a class path (folders and jars separated by '" + File.pathSeparator + "')")));
                case "-h", "--help" -> help = true;
                default -> throw new ConfigException((flag.startsWith("-") ? "unknown option " + flag
                        + Suggestion.didYouMean(flag, Suggestion.optionsIn(USAGE)) : "unexpected argument " + flag)
                        + "\n" + USAGE);
            }
        }
        return new ServerArguments(p, f, help, port, headless, classPath);
    }

    /** The non-empty entries of a class path written with the platform's separator. */
    public static List<String> entries(String path) {
        List<String> entries = new ArrayList<>();
        for (String e : Arrays.asList(path.split(File.pathSeparator))) {
            if (!e.isEmpty()) {
                entries.add(e);
            }
        }
        return entries;
    }

    private static int port(String value) throws ConfigException {
        try {
            int port = Integer.parseInt(value);
            if (port >= 1 && port <= 65535) {
                return port;
            }
        } catch (NumberFormatException e) {
            // not a number: the same message as out of range
        }
        throw new ConfigException("--port " + value + ": a port number from 1 to 65535 expected");
    }

    private static String value(String[] args, int i, String message) throws ConfigException {
        if (i >= args.length) {
            throw new ConfigException(message);
        }
        return args[i];
    }
}
