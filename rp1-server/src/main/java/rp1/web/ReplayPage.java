package rp1.web;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import rp1.io.WholeFiles;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.simulator.record.RecordingException;
import rp1.simulator.record.RecordingReader;
import rp1.simulator.record.Replayer;

/** Writes the replay page of a run (docs/recording.md, "The replay page"). */
public final class ReplayPage {
    /** A replay for a page alone says nothing. */
    private static final RsLogInterface QUIET = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
        }
    };

    private ReplayPage() {
    }

    /**
     * Replays {@code recording} to its end and writes its page to {@code page}.
     *
     * @throws RecordingException if the recording cannot be replayed
     * @throws IOException        if the page cannot be written
     */
    public static void write(Path recording, String title, Path page) throws RecordingException, IOException {
        Replayer replayer = Replayer.prepare(RecordingReader.read(recording), null, QUIET);
        RunTrace trace = RunTrace.attach(replayer.simulation());
        Replayer.Outcome outcome = replayer.run(Double.POSITIVE_INFINITY);
        write(trace, title, outcome.time(), page);
    }

    /**
     * Stops {@code trace}, whose simulation has stopped at simulated time {@code end}, and writes the
     * page of what it gathered to {@code page} (whole or not at all: as {@code page.part}, then renamed).
     */
    public static void write(RunTrace trace, String title, double end, Path page) throws IOException {
        trace.close();
        String html = Page.replay(title, trace.planJson(), List.of(trace.drain()), end);
        WholeFiles.writeString(page, html);
    }
}
