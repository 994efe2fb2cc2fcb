package rp1.planparser;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.zip.GZIPInputStream;

/**
 * Stage's own map images ({@code worlds/bitmaps/} of its source archive), which are test inputs kept
 * outside the repository: read from {@code ../shared/peers/stage-4.3.0-src.tar.gz} when it is beside
 * the project, and the calling test is skipped, with the reason, when it is not. The archive is read
 * with a few lines of tar (512-byte headers, octal sizes), so no {@code tar} command is needed.
 */
public final class StageMaps {
    private static final int BLOCK = 512;

    private StageMaps() {
    }

    public static Path archive() {
        return TestPlans.root().resolve("../shared/peers/stage-4.3.0-src.tar.gz").normalize();
    }

    /** Extracts {@code names} (file names in worlds/bitmaps/) into {@code dir}; skips the test without the archive. */
    public static void extract(Path dir, Set<String> names) throws IOException {
        Path archive = archive();
        assumeTrue(Files.isRegularFile(archive), () -> "skipped: " + archive + " is absent; Stage's maps are test inputs"
                + " kept outside the repository, read only when ../shared/peers is beside it");
        try (InputStream in = new BufferedInputStream(new GZIPInputStream(Files.newInputStream(archive), 1 << 16))) {
            byte[] header = new byte[BLOCK];
            while (in.readNBytes(header, 0, BLOCK) == BLOCK && header[0] != 0) {
                String name = field(header, 0, 100);
                String prefix = field(header, 345, 155);
                String path = prefix.isEmpty() ? name : prefix + "/" + name;
                long size = Long.parseLong(field(header, 124, 12).trim(), 8);
                byte[] data = in.readNBytes((int) size);
                in.skipNBytes((BLOCK - size % BLOCK) % BLOCK);
                String file = path.substring(path.lastIndexOf('/') + 1);
                if (path.contains("worlds/bitmaps/") && names.contains(file)) {
                    Files.write(dir.resolve(file), data);
                }
            }
        }
        for (String name : names) {
            if (!Files.isRegularFile(dir.resolve(name))) {
                throw new IOException(name + " is not in " + archive);
            }
        }
    }

    private static String field(byte[] header, int offset, int length) {
        int end = offset;
        while (end < offset + length && header[end] != 0) {
            end++;
        }
        return new String(header, offset, end - offset, StandardCharsets.US_ASCII);
    }
}
