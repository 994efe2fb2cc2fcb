package rp1.simulator.config;

/**
 * The server's command line: {@code -p PROPERTIES} and {@code -f PLAN}, as RP1 0.60 reads it (the
 * last occurrence of a flag wins; other arguments are ignored).
 */
public final class ServerArguments {
    /** The properties file named with -p, or null for the default RP1.ini. */
    public final String propertiesName;
    /** The floor plan named with -f, or null to use the properties' floorPlanFileName. */
    public final String planName;

    private ServerArguments(String propertiesName, String planName) {
        this.propertiesName = propertiesName;
        this.planName = planName;
    }

    /** Parses the arguments; a flag without a value is an error. */
    public static ServerArguments parse(String[] args) throws ConfigException {
        String p = null;
        String f = null;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("-p")) {
                p = value(args, ++i, "Missing specification for -p option (a properties file)");
            } else if (args[i].equals("-f")) {
                f = value(args, ++i, "Missing specification for -f option (a floor plan)");
            }
        }
        return new ServerArguments(p, f);
    }

    private static String value(String[] args, int i, String message) throws ConfigException {
        if (i >= args.length) {
            throw new ConfigException(message);
        }
        return args[i];
    }
}
