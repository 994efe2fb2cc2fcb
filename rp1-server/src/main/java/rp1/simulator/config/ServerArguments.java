package rp1.simulator.config;

/**
 * The server's command line: {@code -p PROPERTIES} and {@code -f PLAN}, as RP1 0.60 reads it (the
 * last occurrence of a flag wins), and {@code -h}/{@code --help}. Anything else is refused with the
 * usage (RP1 0.60 ignored it, so a mistyped option went unnoticed).
 */
public final class ServerArguments {
    /** What the command line may hold. */
    public static final String USAGE = String.join("\n",
            "usage: java rp1.Server [-p PROPERTIES] [-f FLOORPLAN]",
            "  -p PROPERTIES  properties file: a path, or Properties/NAME on the class path (default Properties/RP1.ini)",
            "  -f FLOORPLAN   floor plan to use instead of the properties' floorPlanFileName",
            "  -h, --help     print this and exit");

    /** The properties file named with -p, or null for the default RP1.ini. */
    public final String propertiesName;
    /** The floor plan named with -f, or null to use the properties' floorPlanFileName. */
    public final String planName;
    /** Whether the usage was asked for ({@code -h}, {@code --help}). */
    public final boolean help;

    private ServerArguments(String propertiesName, String planName, boolean help) {
        this.propertiesName = propertiesName;
        this.planName = planName;
        this.help = help;
    }

    /** Parses the arguments; a flag without a value, or an argument it does not know, is an error. */
    public static ServerArguments parse(String[] args) throws ConfigException {
        String p = null;
        String f = null;
        boolean help = false;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("-p")) {
                p = value(args, ++i, "Missing specification for -p option (a properties file)");
            } else if (args[i].equals("-f")) {
                f = value(args, ++i, "Missing specification for -f option (a floor plan)");
            } else if (args[i].equals("-h") || args[i].equals("--help")) {
                help = true;
            } else {
                throw new ConfigException((args[i].startsWith("-") ? "unknown option " : "unexpected argument ")
                        + args[i] + "\n" + USAGE);
            }
        }
        return new ServerArguments(p, f, help);
    }

    private static String value(String[] args, int i, String message) throws ConfigException {
        if (i >= args.length) {
            throw new ConfigException(message);
        }
        return args[i];
    }
}
