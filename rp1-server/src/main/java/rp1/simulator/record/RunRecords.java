package rp1.simulator.record;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import rp1.io.IoFailures;
import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;

/**
 * What a server keeps of its run: the recording ({@code recordFileName}) and the event log
 * ({@code eventLogFileName}), either or both. Opened before the run starts, closed once the
 * scheduler has stopped. While the run goes, both are put on disk once a wall-clock second, so a
 * process that is killed loses at most its last second; a run at {@code simulationSpeed=max} pays
 * for one write a second, not one per line.
 *
 * <p>One thread does the flushing for every run in the process (a flush hands buffered bytes to the
 * operating system): a sweep's thousand short runs start no thread each for it.
 */
public final class RunRecords implements AutoCloseable {
    /** Wall-clock time between two flushes. */
    private static final long FLUSH_MILLIS = 1000;

    private final Recorder recorder;
    private final EventStream events;
    /** The periodic flush, or null when nothing is kept. */
    private final ScheduledFuture<?> flushing;

    private RunRecords(Recorder recorder, EventStream events) {
        this.recorder = recorder;
        this.events = events;
        flushing = events == null ? null
                : Flusher.THREAD.scheduleWithFixedDelay(this::flush, FLUSH_MILLIS, FLUSH_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** The flushing thread, started with the first run that keeps records (a daemon: it never holds the JVM). */
    private static final class Flusher {
        static final ScheduledThreadPoolExecutor THREAD = start();

        private static ScheduledThreadPoolExecutor start() {
            ScheduledThreadPoolExecutor e = new ScheduledThreadPoolExecutor(1, r -> {
                Thread t = new Thread(r, "rp1-records-flush");
                t.setDaemon(true);
                return t;
            });
            // A closed run's flush leaves the queue at once rather than when it would have been due.
            e.setRemoveOnCancelPolicy(true);
            return e;
        }
    }

    /** Nothing kept. */
    public static RunRecords none() {
        return new RunRecords(null, null);
    }

    /**
     * Opens what is asked for and attaches it to {@code simulation}.
     *
     * @param recording where to record the run, or null
     * @param eventLog  where to log the events, or null
     * @throws IOException naming the file that cannot be created; nothing is left open
     */
    public static RunRecords open(Simulation simulation, Recorder.Header header, Path recording, Path eventLog,
                                  RsLogInterface log) throws IOException {
        if (recording == null && eventLog == null) {
            return none();
        }
        EventStream events = eventLog == null ? EventStream.counting() : openEventLog(eventLog, log);
        Recorder recorder = null;
        if (recording != null) {
            try {
                recorder = Recorder.open(recording, header, simulation.getScheduler(), log);
            } catch (IOException e) {
                events.abandon();
                throw new IOException("cannot create the recording " + recording + " (recordFileName): " + IoFailures.why(e), e);
            }
            simulation.getInputs().setListener(recorder);
            events.watchTasks(simulation.getScheduler()::modelTasksRun);
        }
        simulation.addEventListener(events);
        return new RunRecords(recorder, events);
    }

    private static EventStream openEventLog(Path file, RsLogInterface log) throws IOException {
        try {
            return EventStream.toFile(file, log);
        } catch (IOException e) {
            throw new IOException("cannot create the event log " + file + " (eventLogFileName): " + IoFailures.why(e), e);
        }
    }

    private void flush() {
        events.flush();
        if (recorder != null) {
            recorder.flush();
        }
    }

    /**
     * Writes the end of the recording and finishes both files under their names; call after the
     * scheduler has stopped. What could not be written is then in {@link #failures()}.
     */
    @Override
    public void close() {
        if (flushing != null) {
            flushing.cancel(false);
        }
        if (recorder != null) {
            recorder.close(events);
        }
        if (events != null) {
            events.close();
        }
    }

    /**
     * What could not be written (each naming its file and the error), empty when every file is whole.
     * A run with failures must not pass for a kept one: the server exits with a status of its own.
     */
    public List<String> failures() {
        List<String> failures = new ArrayList<>();
        if (recorder != null && recorder.failure() != null) {
            failures.add(recorder.failure());
        }
        if (events != null && events.failure() != null) {
            failures.add(events.failure());
        }
        return failures;
    }
}
