package rp1.simulator.batch;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import java.util.zip.CRC32;

/**
 * A fingerprint of the code that is a sweep's robot, so that {@code --resume} does not mix the rows of
 * two versions of it: the bytes of every jar on the robot's class path ({@code -cp}) and of the jar
 * each robot class comes from, the class files under every folder among them, and the files a
 * {@code --client} command names (its words that are files, such as {@code robot.py} in
 * {@code python3 robot.py}). Other files a program reads, and resources in folders, are not looked
 * at. A CRC-32 (computed by the JDK's native code: a sweep computes it before its first run) is
 * enough to tell a rebuilt robot from the one before; it is no protection against forgery.
 */
final class RobotCode {
    private RobotCode() {
    }

    /**
     * The fingerprint, as hex digits.
     *
     * @param classPath  the sweep's {@code -cp} entries
     * @param classes    the robot classes the runs load ({@code dlcName})
     * @param loader     the loader the runs find them with
     * @param client     the {@code --client} command, or null
     * @param workingDirectory where the command's relative file names are found
     */
    static String fingerprint(List<Path> classPath, Collection<String> classes, ClassLoader loader, String client,
                              Path workingDirectory) {
        Set<Path> places = new LinkedHashSet<>(classPath);
        for (String name : classes) {
            Path from = origin(loader.getResource(name.replace('.', '/') + ".class"), name);
            if (from != null) {
                places.add(from);
            }
        }
        CRC32 crc = new CRC32();
        try {
            for (Path p : places) {
                add(crc, p);
            }
            if (client != null) {
                for (String word : client.trim().split("\\s+")) {
                    Path file = workingDirectory.resolve(word);
                    if (!word.isEmpty() && Files.isRegularFile(file)) {
                        add(crc, file);
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return String.format("%08x", crc.getValue());
    }

    /** The jar or class folder a class was found in, or null if not a file of this machine. */
    private static Path origin(URL url, String className) {
        if (url == null) {
            return null;
        }
        try {
            if (url.getProtocol().equals("jar")) {
                URL jar = ((JarURLConnection) url.openConnection()).getJarFileURL();
                return jar.getProtocol().equals("file") ? Paths.get(jar.toURI()) : null;
            }
            if (url.getProtocol().equals("file")) {
                Path file = Paths.get(url.toURI());
                // The class file's folder, up one level per package name.
                for (int i = 0; i < className.split("\\.").length && file != null; i++) {
                    file = file.getParent();
                }
                return file;
            }
        } catch (IOException | URISyntaxException | IllegalArgumentException e) {
            return null;
        }
        return null;
    }

    /** A file's name and bytes; a folder's class files', in the order of their names. */
    private static void add(CRC32 crc, Path place) throws IOException {
        if (Files.isRegularFile(place)) {
            file(crc, place, String.valueOf(place.getFileName()));
        } else if (Files.isDirectory(place)) {
            List<Path> files = new ArrayList<>();
            try (Stream<Path> all = Files.walk(place)) {
                all.filter(f -> f.toString().endsWith(".class") && Files.isRegularFile(f)).forEach(files::add);
            }
            files.sort(null);
            for (Path f : files) {
                file(crc, f, place.relativize(f).toString());
            }
        }
    }

    private static void file(CRC32 crc, Path file, String name) throws IOException {
        crc.update(name.getBytes(StandardCharsets.UTF_8));
        crc.update(0);
        crc.update(Files.readAllBytes(file));
    }
}
