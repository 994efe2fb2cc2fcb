package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsLogAdapter;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.SimClock;

/**
 * A disk that fills up while the run goes: the periodic flush is where it shows, the file stops, the
 * log says so at the important level, and the failure is kept for the server's exit status.
 */
class WriteFailureTest {
    private static final Path FILE = Paths.get("run.out");

    private final List<String> important = new ArrayList<>();
    private final RsLogAdapter log = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
            if (level.equals("X")) {
                important.add(message);
            }
        }
    };

    /** What a full disk does: accepts nothing. Buffered, as files are, so it shows at the flush. */
    private static RunFile fullDisk() {
        return RunFile.over(new BufferedOutputStream(new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("No space left on device");
            }
        }, 1 << 16), FILE);
    }

    @Test
    void aRecordingThatCannotBeFlushedStopsAndSaysWhy() throws Exception {
        Recorder recorder = Recorder.open(fullDisk(), new Recorder.Header(Map.of("randomSeed", "1"), "room.txt",
                "caption: \"room\";", 1), new Scheduler(SimClock.lockstep()), log);
        assertNull(recorder.failure(), "nothing has reached the disk yet");

        recorder.flush();
        assertEquals("the recording run.out stops at 0.0 s: cannot write: No space left on device; what was recorded is"
                + " in run.out", recorder.failure());
        assertEquals(List.of("The recording run.out stops here: cannot write: No space left on device"), important);
        recorder.close(EventStream.counting());
        assertTrue(recorder.failure().startsWith("the recording run.out stops at 0.0 s"), "the first failure is kept");
    }

    @Test
    void anEventLogThatCannotBeFlushedStopsAndSaysWhy() throws Exception {
        EventStream events = EventStream.toFile(fullDisk(), log);
        events.flush();
        assertEquals("cannot write the event log run.out: No space left on device; the events logged before are in"
                + " run.out", events.failure());
        assertEquals(List.of(events.failure()), important);
        events.close();
        assertEquals(1, important.size(), "a stopped log is not finished again");
    }
}
