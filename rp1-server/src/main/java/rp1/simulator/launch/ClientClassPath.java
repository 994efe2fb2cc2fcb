package rp1.simulator.launch;

import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The class path given with {@code -cp} for the classes a server loads by name ({@code dlcName}):
 * folders and jars relative to the user's working directory, searched after the simulator's own
 * class path, so a robot of one's own runs without rebuilding the simulator's class path.
 */
public final class ClientClassPath {
    private ClientClassPath() {
    }

    /**
     * The entries resolved against {@code workingDirectory}, made absolute.
     *
     * @throws StartupException naming the first entry that is neither a folder nor a file
     */
    public static List<Path> resolve(List<String> entries, Path workingDirectory) throws StartupException {
        List<Path> paths = new ArrayList<>();
        for (String entry : entries) {
            Path p = workingDirectory.resolve(entry).toAbsolutePath().normalize();
            if (!Files.exists(p)) {
                throw new StartupException("class path entry " + entry + " not found (looked for " + p + ")");
            }
            paths.add(p);
        }
        return paths;
    }

    /** {@code parent} itself when {@code entries} is empty, else a loader over them that asks {@code parent} first. */
    public static ClassLoader loader(List<Path> entries, ClassLoader parent) {
        if (entries.isEmpty()) {
            return parent;
        }
        URL[] urls = new URL[entries.size()];
        for (int i = 0; i < urls.length; i++) {
            try {
                urls[i] = entries.get(i).toUri().toURL();
            } catch (MalformedURLException e) {
                throw new IllegalArgumentException("class path entry " + entries.get(i) + ": " + e.getMessage(), e);
            }
        }
        return new URLClassLoader("rp1 -cp", urls, parent);
    }
}
