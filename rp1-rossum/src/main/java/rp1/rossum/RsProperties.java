package rp1.rossum;

import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Locale;
import java.util.Properties;

/**
 * A client's configuration: where the server is ({@code hostName}, {@code port}) and how to log
 * ({@code logFileName}, {@code logToFile}, {@code logToSystemOut}, {@code logVerbose}). Read from
 * standard Java properties files named {@code rossum.ini}; only the first word of each value counts,
 * so trailing comments are harmless. Every load merges into the same table and re-validates;
 * invalid values raise {@link RsPropertiesException} naming the key, the value and the source.
 */
public class RsProperties extends Properties {
    private static final long serialVersionUID = 1L;

    /** Name of the client properties file, in the working directory or as a resource. */
    public static final String FILE_NAME = "rossum.ini";
    /** The lowest port accepted (RP1 0.60: 1025). */
    public static final int MIN_PORT = 1;
    /** The highest port accepted (RP1 0.60: 32767). */
    public static final int MAX_PORT = 65535;

    /** The server's port ({@code port}); 7758 by default. */
    public int port;
    /** The server's host ({@code hostName}); 127.0.0.1 by default. */
    public String hostName;
    /**
     * The log file ({@code logFileName}), used when {@link #logToFile} is on; rossum.log by
     * default.
     */
    public String logFileName;
    /** Whether verbose lines are logged ({@code logVerbose}); off by default. */
    public boolean logVerbose;
    /** Whether the client logs to {@link #logFileName} ({@code logToFile}); off by default. */
    public boolean logToFile;
    /** Whether the client logs to standard output ({@code logToSystemOut}); on by default. */
    public boolean logToSystemOut;

    /**
     * The library defaults, then the {@code rossum.ini} packaged with the library. A problem with the
     * packaged file is reported on standard error and the defaults stay.
     */
    public RsProperties() {
        applyDefaults();
        try {
            loadFromResource(this, FILE_NAME);
        } catch (RsPropertiesException e) {
            warn("RsProperties: packaged " + FILE_NAME + " not applied: " + e.getMessage());
        }
    }

    /**
     * The library defaults, then {@code -p FILE} if given (else {@code ./rossum.ini} if present), then
     * the command-line overrides; see {@link #processArgs}.
     */
    public RsProperties(String[] args) throws RsPropertiesException {
        applyDefaults();
        processArgs(args);
    }

    private void applyDefaults() {
        port = 7758;
        hostName = "127.0.0.1";
        logFileName = "rossum.log";
        logToFile = false;
        logToSystemOut = true;
        logVerbose = false;
    }

    /**
     * Loads {@code -p FILE} (or {@code ./rossum.ini} if it exists), then applies {@code -port},
     * {@code -hostName}, {@code -logFileName}, {@code -logToFile}, {@code -logVerbose} and
     * {@code -logToSystemOut}, each followed by its value.
     */
    public void processArgs(String[] args) throws RsPropertiesException {
        String file = optionValue(args, "-p");
        if (file != null) {
            loadFromFile(file);
        } else if (Files.isRegularFile(Paths.get(FILE_NAME))) {
            loadFromFile(FILE_NAME);
        }
        boolean changed = false;
        for (String key : new String[] {"port", "hostName", "logFileName", "logToFile", "logVerbose", "logToSystemOut"}) {
            String value = optionValue(args, "-" + key);
            if (value != null) {
                setProperty(key, value);
                changed = true;
            }
        }
        if (changed) {
            extract("command line");
        }
    }

    private static String optionValue(String[] args, String option) throws RsPropertiesException {
        if (args == null) {
            return null;
        }
        String value = null;
        for (int i = 0; i < args.length; i++) {
            if (option.equals(args[i])) {
                if (i + 1 >= args.length || args[i + 1].startsWith("-")) {
                    throw new RsPropertiesException("Missing specification for " + option + " option");
                }
                value = args[++i];
            }
        }
        return value;
    }

    /** Same as {@link #loadFromFile}. */
    public void load(String fileName) throws RsPropertiesException {
        loadFromFile(fileName);
    }

    /** Merges the properties file {@code fileName} (a path) and re-validates. */
    public void loadFromFile(String fileName) throws RsPropertiesException {
        try (InputStream in = new FileInputStream(fileName)) {
            load(in, fileName);
        } catch (RsPropertiesException e) {
            throw e;
        } catch (IOException e) {
            throw new RsPropertiesException("Unable to read properties file " + fileName + ": " + e.getMessage());
        }
    }

    /** Merges the resource {@code resource}, looked up relative to the class of {@code anchor}. */
    public void loadFromResource(Object anchor, String resource) throws RsPropertiesException {
        Class<?> c = anchor instanceof Class ? (Class<?>) anchor : anchor.getClass();
        String source = "resource " + resource + " of " + c.getName();
        try (InputStream in = c.getResourceAsStream(resource)) {
            if (in == null) {
                throw new RsPropertiesException("Unable to find " + source);
            }
            load(in, source);
        } catch (RsPropertiesException e) {
            throw e;
        } catch (IOException e) {
            throw new RsPropertiesException("Unable to read " + source + ": " + e.getMessage());
        }
    }

    /** Merges properties from a stream and re-validates. */
    @Override
    public void load(InputStream in) throws RsPropertiesException {
        load(in, "properties stream");
    }

    private void load(InputStream in, String source) throws RsPropertiesException {
        try {
            super.load(in);
        } catch (IOException | IllegalArgumentException e) {
            throw new RsPropertiesException("Unable to read " + source + ": " + e.getMessage());
        }
        extract(source);
    }

    /** Re-reads the public fields from the table, validating them. */
    private void extract(String source) throws RsPropertiesException {
        String host = firstWord(getProperty("hostName"));
        if (host == null) {
            throw new RsPropertiesException("Missing mandatory specification for hostName (" + source + ")");
        }
        int p = parsePort(firstWord(getProperty("port")), source);
        boolean toFile = extractBoolean("logToFile", source);
        boolean toOut = extractBoolean("logToSystemOut", source);
        boolean verbose = extractBoolean("logVerbose", source);
        String file = firstWord(getProperty("logFileName"));
        if (toFile && file == null) {
            throw new RsPropertiesException("The logToFile option was requested, but logFileName is missing (" + source + ")");
        }
        hostName = host;
        port = p;
        logToFile = toFile;
        logToSystemOut = toOut;
        logVerbose = verbose;
        if (file != null) {
            logFileName = file;
        }
    }

    private static int parsePort(String value, String source) throws RsPropertiesException {
        if (value == null) {
            throw new RsPropertiesException("Missing mandatory specification for port (" + source + ")");
        }
        int p;
        try {
            p = Integer.parseInt(value);
        } catch (NumberFormatException e) {
            throw new RsPropertiesException("Bad number format for integer port specification: \"" + value + "\" (" + source + ")");
        }
        if (p < MIN_PORT || p > MAX_PORT) {
            throw new RsPropertiesException("Integer port number " + p + " not in valid range [" + MIN_PORT + ","
                    + MAX_PORT + "] (" + source + ")");
        }
        return p;
    }

    private boolean extractBoolean(String key, String source) throws RsPropertiesException {
        String v = firstWord(getProperty(key));
        if (v == null) {
            return false;
        }
        String lower = v.toLowerCase(Locale.ROOT);
        if (lower.equals("true")) {
            return true;
        }
        if (lower.equals("false")) {
            return false;
        }
        throw new RsPropertiesException("Invalid specification where true/false expected for " + key + ": \"" + v
                + "\" (" + source + ")");
    }

    /** The value of {@code key} as a double (first word only). */
    public double extractDouble(String key) throws RsPropertiesException {
        String v = requireValue(key);
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new RsPropertiesException("Bad number format for " + key + ": \"" + v + "\"");
        }
    }

    /** The value of {@code key} as an int (first word only). */
    public int extractInt(String key) throws RsPropertiesException {
        String v = requireValue(key);
        try {
            return Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new RsPropertiesException("Bad number format for integer " + key + ": \"" + v + "\"");
        }
    }

    private String requireValue(String key) throws RsPropertiesException {
        String v = firstWord(getProperty(key));
        if (v == null) {
            throw new RsPropertiesException("Missing specification for " + key);
        }
        return v;
    }

    /** The first white-space-delimited word of a value, or null if there is none. */
    public static String firstWord(String value) {
        if (value == null) {
            return null;
        }
        String trimmed = value.trim();
        if (trimmed.isEmpty()) {
            return null;
        }
        int end = 0;
        while (end < trimmed.length() && !Character.isWhitespace(trimmed.charAt(end))) {
            end++;
        }
        return trimmed.substring(0, end);
    }

    private static void warn(String message) {
        PrintStream err = System.err;
        err.println(message);
    }
}
