package rp1.simulator.record;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.function.LongSupplier;
import java.util.zip.CRC32;

import rp1.io.IoFailures;
import rp1.rossum.RsLogInterface;
import rp1.rossum.event.RsEvent;
import rp1.simulator.Simulation;
import rp1.simulator.session.ClientSession;

/**
 * Every event sent to a client, as one line of text each ({@link EventText}): written to an event log
 * if there is one, and counted and checksummed, so that a recording can say what its replay must
 * give. The live run and its replay both write through here, on the thread running tasks. The log
 * is {@code NAME.part} until it is closed ({@link RunFile}); {@link #flush()} puts it on disk.
 */
public final class EventStream implements Simulation.EventListener {
    /** The version of the event log's line format: raise it when a line changes. */
    private static final int VERSION = 1;
    /** The first line of every event log. */
    private static final String HEADER = "# rp1-events " + VERSION;

    private final CRC32 checksum = new CRC32();
    private final RsLogInterface log;
    private RunFile out;
    private long count;
    private String failure;
    /** The model tasks run so far, while events are sent; null if not watched. */
    private LongSupplier tasks;
    /** The count and checksum before the first event sent while {@code markTask} tasks had run. */
    private long markTask = -1;
    private long markCount;
    private long markChecksum;

    private EventStream(RunFile out, RsLogInterface log) {
        this.out = out;
        this.log = log;
    }

    /** A stream that only counts and checksums. */
    public static EventStream counting() {
        return new EventStream(null, null);
    }

    /**
     * A stream that also writes the event log {@code file} (created or truncated).
     *
     * @param log where a failure to write is reported (the run goes on without the log)
     */
    public static EventStream toFile(Path file, RsLogInterface log) throws IOException {
        return toFile(RunFile.create(file), log);
    }

    static EventStream toFile(RunFile file, RsLogInterface log) throws IOException {
        try {
            file.write((HEADER + '\n').getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            file.abandon();
            throw e;
        }
        return new EventStream(file, log);
    }

    @Override
    public synchronized void event(ClientSession session, RsEvent event, boolean delivered) {
        if (!delivered) {
            return;
        }
        // One encoding serves the checksum and the file.
        byte[] line = (EventText.line(session.getNumber(), event) + '\n').getBytes(StandardCharsets.UTF_8);
        if (tasks != null) {
            long k = tasks.getAsLong();
            if (k != markTask) {
                markTask = k;
                markCount = count;
                markChecksum = checksum.getValue();
            }
        }
        checksum.update(line);
        count++;
        if (out != null) {
            try {
                out.write(line);
            } catch (IOException e) {
                stop("cannot write the event log " + out.file() + ": " + IoFailures.why(e));
            }
        }
    }

    /**
     * Watches how many model tasks have run as events are sent ({@code tasks}, read on the thread that
     * sends them), so that {@link #before} can leave out the events of a task that never finished.
     */
    public synchronized void watchTasks(LongSupplier tasks) {
        this.tasks = tasks;
    }

    /**
     * The count and checksum of the events sent before the task that ran after {@code task} model
     * tasks had: those of the finished tasks, when that one never finished (a robot's handler that
     * never returned as the server stopped). All of them if it sent none, or nothing is watched.
     */
    public synchronized long[] before(long task) {
        return tasks != null && markTask == task ? new long[] {markCount, markChecksum}
                : new long[] {count, checksum.getValue()};
    }

    /** Puts the events logged so far on disk; a failure stops the log. Any thread. */
    public synchronized void flush() {
        if (out == null) {
            return;
        }
        try {
            out.flush();
        } catch (IOException e) {
            stop("cannot write the event log " + out.file() + ": " + IoFailures.why(e));
        }
    }

    /** Why the event log is not whole (it could not be written or finished), or null. */
    public synchronized String failure() {
        return failure;
    }

    /** The log stops here; the events are still counted, for the recording's end. */
    private void stop(String why) {
        failure = why + "; the events logged before are in " + out.unfinished();
        log.logIt("X", failure);
        out.abandon();
        out = null;
    }

    /** Events sent so far. */
    public synchronized long count() {
        return count;
    }

    /** CRC-32 of the event lines so far (each with its line feed, in UTF-8). */
    public synchronized long checksum() {
        return checksum.getValue();
    }

    /** Closes the event log without finishing it (the run did not start), leaving it as {@code NAME.part}. */
    synchronized void abandon() {
        if (out != null) {
            out.abandon();
            out = null;
        }
    }

    /** Finishes the event log, if any, under its final name; a failure is {@link #failure()}. */
    public synchronized void close() {
        if (out == null) {
            return;
        }
        try {
            out.finish();
            out = null;
        } catch (IOException e) {
            stop("cannot finish the event log " + out.file() + ": " + e.getMessage());
        }
    }
}
