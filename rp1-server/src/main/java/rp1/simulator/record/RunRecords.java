package rp1.simulator.record;

import java.io.IOException;
import java.nio.file.Path;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;

/**
 * What a server keeps of its run: the recording ({@code recordFileName}) and the event log
 * ({@code eventLogFileName}), either or both. Opened before the run starts, closed once the
 * scheduler has stopped.
 */
public final class RunRecords implements AutoCloseable {
    private final Recorder recorder;
    private final EventStream events;
    private final RsLogInterface log;

    private RunRecords(Recorder recorder, EventStream events, RsLogInterface log) {
        this.recorder = recorder;
        this.events = events;
        this.log = log;
    }

    /** Nothing kept. */
    public static RunRecords none() {
        return new RunRecords(null, null, null);
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
                events.close();
                throw new IOException("cannot create the recording " + recording + " (recordFileName): " + e.getMessage(), e);
            }
            simulation.getInputs().setListener(recorder);
        }
        simulation.addEventListener(events);
        return new RunRecords(recorder, events, log);
    }

    private static EventStream openEventLog(Path file, RsLogInterface log) throws IOException {
        try {
            return EventStream.toFile(file, log);
        } catch (IOException e) {
            throw new IOException("cannot create the event log " + file + " (eventLogFileName): " + e.getMessage(), e);
        }
    }

    /** Writes the end of the recording and closes both files; call after the scheduler has stopped. */
    @Override
    public void close() {
        if (recorder != null) {
            recorder.close(events);
        }
        if (events != null) {
            try {
                events.close();
            } catch (IOException e) {
                log.logIt("X", "Cannot finish the event log: " + e.getMessage());
            }
        }
    }
}
