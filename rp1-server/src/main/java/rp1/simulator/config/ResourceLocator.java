package rp1.simulator.config;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.io.StringReader;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

import rp1.io.IoFailures;

/**
 * Finds the server's properties file and floor plan. A properties name given with {@code -p} is
 * looked for in the working directory, then as {@code Properties/NAME} on the class path; without
 * {@code -p} the class-path {@code Properties/RP1.ini} is used. A floor plan is looked for as a path,
 * then in {@code FloorPlans/} of the working directory, then as {@code FloorPlans/NAME} on the class
 * path.
 */
public final class ResourceLocator {
    /** The properties used when no -p is given. */
    public static final String DEFAULT_PROPERTIES = "RP1.ini";

    private final Path workingDirectory;
    private final ClassLoader classLoader;

    public ResourceLocator(Path workingDirectory, ClassLoader classLoader) {
        this.workingDirectory = workingDirectory;
        this.classLoader = classLoader;
    }

    /** Text found somewhere, with a description of where (a path or a class-path URL). */
    public static final class Found {
        public final String text;
        public final String location;

        Found(String text, String location) {
            this.text = text;
            this.location = location;
        }

        public Reader reader() {
            return new StringReader(text);
        }
    }

    /** Reads the server properties named with -p (or the default RP1.ini if {@code name} is null). */
    public Found properties(String name) throws ConfigException {
        if (name == null) {
            return resource("Properties/" + DEFAULT_PROPERTIES, "the default properties " + DEFAULT_PROPERTIES);
        }
        Path file = workingDirectory.resolve(name);
        if (Files.isRegularFile(file)) {
            return file(file);
        }
        if (Files.isDirectory(file)) {
            throw new ConfigException("properties " + name + ": " + file.toAbsolutePath() + " is a folder, not a file");
        }
        return resource("Properties/" + name, "properties " + name
                + " (looked in " + workingDirectory.toAbsolutePath() + " and on the class path)");
    }

    /** Parses properties text; {@code location} names it in errors. */
    public static Properties parseProperties(Found found) throws ConfigException {
        Properties p = new Properties();
        try {
            p.load(found.reader());
        } catch (IOException | IllegalArgumentException e) {
            throw new ConfigException(found.location + ": not a valid properties file: " + e.getMessage());
        }
        return p;
    }

    /** Reads a floor plan. */
    public Found plan(String name) throws ConfigException {
        Path direct = workingDirectory.resolve(name);
        if (Files.isRegularFile(direct)) {
            return file(direct);
        }
        if (Files.isDirectory(direct)) {
            throw new ConfigException("floor plan " + name + ": " + direct.toAbsolutePath() + " is a folder, not a file");
        }
        Path inFolder = workingDirectory.resolve("FloorPlans").resolve(name);
        if (Files.isRegularFile(inFolder)) {
            return file(inFolder);
        }
        return resource("FloorPlans/" + name, "floor plan " + name + " (looked in "
                + workingDirectory.toAbsolutePath() + ", its FloorPlans folder and the class path)");
    }

    private static Found file(Path file) throws ConfigException {
        try {
            return new Found(new String(Files.readAllBytes(file), StandardCharsets.UTF_8), file.toString());
        } catch (IOException e) {
            throw new ConfigException("cannot read " + file + ": " + IoFailures.why(e), e);
        }
    }

    private Found resource(String path, String what) throws ConfigException {
        URL url = classLoader.getResource(path);
        if (url == null) {
            throw new ConfigException("cannot find " + what);
        }
        try (InputStream in = url.openStream()) {
            return new Found(new String(in.readAllBytes(), StandardCharsets.UTF_8), url.toString());
        } catch (IOException e) {
            throw new ConfigException("cannot read " + url + ": " + IoFailures.why(e), e);
        }
    }
}
