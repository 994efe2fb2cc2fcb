package rp1.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A failed file operation is told by what went wrong, not by the path alone. */
class IoFailuresTest {
    @TempDir
    Path dir;

    @Test
    void aMissingFileIsSaidToBeMissing() {
        IOException e = assertThrows(IOException.class, () -> Files.readAllBytes(dir.resolve("nosuch.rec")));
        assertEquals("no such file or folder", IoFailures.why(e));
    }

    @Test
    void aFileWhereAFolderShouldBeIsSaidToBeInTheWay() throws IOException {
        Path file = Files.writeString(dir.resolve("ro"), "x");
        IOException e = assertThrows(IOException.class, () -> Files.createDirectories(file));
        assertEquals("a file of that name is in the way", IoFailures.why(e));
        IOException under = assertThrows(IOException.class, () -> Files.writeString(file.resolve("x.png"), "x"));
        assertEquals("Not a directory", IoFailures.why(under), "the system's own reason where Java has no class for it");
    }

    @Test
    void anyOtherFailureKeepsItsMessage() {
        assertEquals("disk full", IoFailures.why(new IOException("disk full")));
        assertEquals("IOException", IoFailures.why(new IOException()));
    }
}
