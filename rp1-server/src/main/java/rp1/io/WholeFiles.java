package rp1.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Files that appear whole or not at all: written as {@code NAME.part} beside their final name, then
 * renamed to it in one step. A reader (a browser, a resumed sweep, a script waiting for results) never
 * sees half a file under the final name, and a write that fails removes its {@code .part} and leaves
 * any older file of that name as it was.
 */
public final class WholeFiles {
    /** Writes the file's content to the path it is given. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Path part) throws IOException;
    }

    private WholeFiles() {
    }

    /** Where {@code file} is written until it is finished: {@code NAME.part} beside it. */
    public static Path partOf(Path file) {
        return file.resolveSibling(file.getFileName() + ".part");
    }

    /** Writes {@code file} with {@code content}, whole or not at all. */
    public static void write(Path file, Content content) throws IOException {
        Path part = partOf(file);
        try {
            content.writeTo(part);
            Files.move(part, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException | RuntimeException e) {
            try {
                Files.deleteIfExists(part);
            } catch (IOException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
    }

    /** Writes {@code text} as UTF-8 to {@code file}, whole or not at all. */
    public static void writeString(Path file, String text) throws IOException {
        write(file, part -> Files.write(part, text.getBytes(StandardCharsets.UTF_8)));
    }
}
