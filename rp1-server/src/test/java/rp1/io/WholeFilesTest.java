package rp1.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A results table, an index page or a picture appears whole under its name, or the old one stays. */
class WholeFilesTest {
    @TempDir
    Path dir;

    @Test
    void aFileWrittenWholeReplacesTheOldOneAndLeavesNoPartBehind() throws IOException {
        Path file = dir.resolve("results.csv");
        Files.writeString(file, "old");
        WholeFiles.writeString(file, "seed,distance\n1,8.3859\n");
        assertEquals("seed,distance\n1,8.3859\n", Files.readString(file, StandardCharsets.UTF_8));
        assertFalse(Files.exists(dir.resolve("results.csv.part")));
    }

    @Test
    void aWriteThatFailsHalfwayLeavesTheOldFileAndNoPart() throws IOException {
        Path file = dir.resolve("summary.png");
        Files.writeString(file, "the picture of the last sweep");
        IOException failure = assertThrows(IOException.class, () -> WholeFiles.write(file, part -> {
            Files.writeString(part, "half a pict");
            throw new IOException("No space left on device");
        }));
        assertEquals("No space left on device", failure.getMessage());
        assertEquals("the picture of the last sweep", Files.readString(file));
        assertFalse(Files.exists(WholeFiles.partOf(file)));
        assertThrows(UncheckedIOException.class, () -> WholeFiles.write(file, part -> {
            Files.writeString(part, "half");
            throw new UncheckedIOException(new IOException("encoder failed"));
        }));
        assertFalse(Files.exists(WholeFiles.partOf(file)));
    }
}
