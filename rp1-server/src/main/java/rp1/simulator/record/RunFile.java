package rp1.simulator.record;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import rp1.io.WholeFiles;

/**
 * A file a run writes as it goes (a recording, an event log): under {@code NAME.part} until the run
 * ends cleanly, then renamed {@code NAME} in one step, so a file under its final name is always whole.
 * What a killed run leaves is in {@code NAME.part}, on disk up to the last {@link #flush()}.
 */
final class RunFile {
    private static final int BUFFER = 1 << 16;

    private final OutputStream out;
    private final Path file;
    private final Path part;

    private RunFile(OutputStream out, Path file, Path part) {
        this.out = out;
        this.file = file;
        this.part = part;
    }

    /**
     * Starts writing {@code file}: creates (or truncates) {@code NAME.part} and removes an older
     * {@code NAME}, which would otherwise pass for this run's if the run never finished. A folder of
     * that name is refused before anything is created: removing it (when empty) or leaving an empty
     * {@code NAME.part} beside it (when not) would be the run's doing, not the user's.
     */
    static RunFile create(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new IOException("it is a folder");
        }
        Path part = WholeFiles.partOf(file);
        OutputStream out = new BufferedOutputStream(Files.newOutputStream(part), BUFFER);
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            out.close();
            throw e;
        }
        return new RunFile(out, file, part);
    }

    /** Writes into {@code out} and renames nothing when finished (tests feed it a stream that fails). */
    static RunFile over(OutputStream out, Path file) {
        return new RunFile(out, file, null);
    }

    /** The file's final name, for messages. */
    Path file() {
        return file;
    }

    /** Where what was written so far is, while the file is not finished or when it failed. */
    Path unfinished() {
        return part == null ? file : part;
    }

    void write(byte[] bytes) throws IOException {
        out.write(bytes);
    }

    /** Hands everything written so far to the operating system: it survives the process being killed. */
    void flush() throws IOException {
        out.flush();
    }

    /** Flushes, closes and gives the file its final name. */
    void finish() throws IOException {
        out.close();
        if (part != null) {
            Files.move(part, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** Closes after a failure, leaving what reached the disk in {@link #unfinished()}. */
    void abandon() {
        try {
            out.close();
        } catch (IOException e) {
            // The failure that brought us here is the one reported; this one adds nothing.
        }
    }
}
