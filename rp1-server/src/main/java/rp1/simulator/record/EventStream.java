package rp1.simulator.record;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;

import rp1.rossum.RsLogInterface;
import rp1.rossum.event.RsEvent;
import rp1.simulator.Simulation;
import rp1.simulator.session.ClientSession;

/**
 * Every event sent to a client, as one line of text each ({@link EventText}): written to an event log
 * if there is one, and counted and checksummed, so that a recording can say what its replay must
 * give. The live run and its replay both write through here, on the thread running tasks.
 */
public final class EventStream implements Simulation.EventListener {
    /** The version of the event log's line format: raise it when a line changes. */
    private static final int VERSION = 1;
    /** The first line of every event log. */
    private static final String HEADER = "# rp1-events " + VERSION;

    private final CRC32 checksum = new CRC32();
    private final RsLogInterface log;
    private final String fileName;
    private OutputStream out;
    private long count;

    private EventStream(OutputStream out, String fileName, RsLogInterface log) {
        this.out = out;
        this.fileName = fileName;
        this.log = log;
    }

    /** A stream that only counts and checksums. */
    public static EventStream counting() {
        return new EventStream(null, null, null);
    }

    /**
     * A stream that also writes the event log {@code file} (created or truncated).
     *
     * @param log where a failure to write is reported (the run goes on without the log)
     */
    public static EventStream toFile(Path file, RsLogInterface log) throws IOException {
        OutputStream w = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16);
        w.write((HEADER + '\n').getBytes(StandardCharsets.UTF_8));
        return new EventStream(w, file.toString(), log);
    }

    @Override
    public synchronized void event(ClientSession session, RsEvent event, boolean delivered) {
        if (!delivered) {
            return;
        }
        // One encoding serves the checksum and the file.
        byte[] line = (EventText.line(session.getNumber(), event) + '\n').getBytes(StandardCharsets.UTF_8);
        checksum.update(line);
        count++;
        if (out != null) {
            try {
                out.write(line);
            } catch (IOException e) {
                log.logIt("X", "Cannot write the event log " + fileName + "; it stops here: " + e.getMessage());
                closeQuietly();
            }
        }
    }

    /** Events sent so far. */
    public synchronized long count() {
        return count;
    }

    /** CRC-32 of the event lines so far (each with its line feed, in UTF-8). */
    public synchronized long checksum() {
        return checksum.getValue();
    }

    /** Flushes and closes the event log, if any. */
    public synchronized void close() throws IOException {
        if (out != null) {
            OutputStream w = out;
            out = null;
            w.close();
        }
    }

    private void closeQuietly() {
        try {
            close();
        } catch (IOException e) {
            log.logIt("X", "Cannot close the event log " + fileName + ": " + e.getMessage());
        }
    }
}
