package rp1.planparser;

import java.io.IOException;
import java.io.InputStream;
import java.net.MalformedURLException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * Finds and reads the image a map names. A relative image name is taken relative to the file that
 * names it (as map_server does), whether that file is a path or a class-path URL; an absolute one as
 * it is.
 */
final class MapSource {
    /** A URL's scheme: two characters at least, so that a Windows drive letter is a path. */
    private static final Pattern URL_SCHEME = Pattern.compile("[A-Za-z][A-Za-z0-9+.-]+:.*");

    private MapSource() {
    }

    /**
     * Where the file {@code image}, named in the file at {@code location}, is: a path or a URL. A URL or
     * an absolute path is taken as it is; anything else is relative to the naming file's folder.
     */
    static String resolve(String location, String image) {
        if (URL_SCHEME.matcher(image).matches() || isAbsolutePath(image)) {
            return image;
        }
        if (URL_SCHEME.matcher(location).matches()) {
            try {
                return new URL(new URL(location), image).toString();
            } catch (MalformedURLException e) {
                return image;
            }
        }
        try {
            Path parent = Path.of(location).getParent();
            return parent == null ? image : parent.resolve(image).toString();
        } catch (InvalidPathException e) {
            return image;
        }
    }

    private static boolean isAbsolutePath(String name) {
        try {
            return Path.of(name).isAbsolute();
        } catch (InvalidPathException e) {
            return false;
        }
    }

    /**
     * The occupied cells of the image at {@code where} (as {@link #resolve} gives it).
     *
     * @throws IOException if it cannot be opened or read; the message says why
     */
    static OccupancyGrid read(String where, MapSpec spec) throws IOException {
        try (InputStream in = open(where)) {
            return MapImageReader.read(in, spec);
        }
    }

    /** The text of the map file at {@code where}, at most {@code limit} characters. */
    static String text(String where, int limit) throws IOException {
        try (InputStream in = open(where)) {
            byte[] bytes = in.readNBytes(limit + 1);
            if (bytes.length > limit) {
                throw new IOException("longer than " + limit + " bytes: not a map file");
            }
            return new String(bytes, StandardCharsets.UTF_8);
        }
    }

    private static InputStream open(String where) throws IOException {
        if (URL_SCHEME.matcher(where).matches()) {
            return new URL(where).openStream();
        }
        Path file;
        try {
            file = Path.of(where);
        } catch (InvalidPathException e) {
            throw new IOException("not a valid file name: " + e.getReason());
        }
        if (!Files.isRegularFile(file)) {
            throw new IOException("no such file");
        }
        return Files.newInputStream(file);
    }
}
