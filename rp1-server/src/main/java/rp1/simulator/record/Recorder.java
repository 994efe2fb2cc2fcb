package rp1.simulator.record;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import rp1.io.IoFailures;
import rp1.rossum.RsLogInterface;
import rp1.simulator.ViewInput;
import rp1.simulator.scheduler.Input;
import rp1.simulator.scheduler.InputQueue;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.session.ClientInput;
import rp1.simulator.world.WorldModel;

/**
 * Writes the recording of a run (docs/recording.md) as it happens: the header when opened, each
 * input as it is applied (with the number of model tasks run before it and its time), and the end
 * when closed. The file is {@code NAME.part} until it is closed ({@link RunFile}); {@link #flush()}
 * puts what was recorded on disk. It never stops the run: if it cannot write, it says so in the log,
 * notes in the file (if it still can) that the recording broke off, and {@link #failure()} says why.
 */
public final class Recorder implements InputQueue.Listener {
    /** What a run starts from. */
    public record Header(Map<String, String> properties, String planName, String planText, long seed) {
    }

    private final Scheduler scheduler;
    private final RsLogInterface log;
    private final String fileName;
    private final Set<Integer> clients = new HashSet<>();
    private RunFile out;
    private String failure;

    private Recorder(RunFile out, Scheduler scheduler, RsLogInterface log) {
        this.out = out;
        this.fileName = out.file().toString();
        this.scheduler = scheduler;
        this.log = log;
    }

    /**
     * Starts the recording {@code file} ({@code NAME.part} until it is closed) and writes the header.
     * Register the recorder with the simulation's input queue before the run starts.
     */
    public static Recorder open(Path file, Header header, Scheduler scheduler, RsLogInterface log) throws IOException {
        return open(RunFile.create(file), header, scheduler, log);
    }

    static Recorder open(RunFile file, Header header, Scheduler scheduler, RsLogInterface log) throws IOException {
        Recorder r = new Recorder(file, scheduler, log);
        try {
            r.writeHeader(header);
        } catch (IOException e) {
            file.abandon();
            throw e;
        }
        return r;
    }

    private void writeHeader(Header h) throws IOException {
        out.write(("# A run of the RP1 simulator; replay it, from the folder it is in, with: rp1 replay "
                + out.file().getFileName() + " (./rp1 from the repository)\n")
                .getBytes(StandardCharsets.UTF_8));
        write(new TextLine(RecordingFormat.MAGIC).integer(RecordingFormat.VERSION));
        write(new TextLine(RecordingFormat.WORLD_MODEL).integer(WorldModel.VERSION));
        write(new TextLine(RecordingFormat.SEED).integer(h.seed()));
        for (Map.Entry<String, String> p : h.properties().entrySet()) {
            write(new TextLine(RecordingFormat.PROPERTY).text(p.getKey()).text(p.getValue()));
        }
        List<String> lines = lines(h.planText());
        write(new TextLine(RecordingFormat.PLAN).text(h.planName()).integer(lines.size()));
        StringBuilder plan = new StringBuilder(h.planText().length() + lines.size() * (RecordingFormat.PLAN_LINE.length() + 1));
        for (String line : lines) {
            plan.append(RecordingFormat.PLAN_LINE).append(line).append('\n');
        }
        out.write(plan.toString().getBytes(StandardCharsets.UTF_8));
    }

    /**
     * The text cut at every line ending ({@code \r\n}, {@code \r} or {@code \n}): the recording's plan
     * lines, the last one empty when the text ends with a line ending. By hand rather than with a
     * regular expression: every run of a sweep writes a header, and the expression's matching was a
     * seventieth of a warm sweep's processor time.
     */
    static List<String> lines(String text) {
        List<String> lines = new ArrayList<>();
        int start = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n' || c == '\r') {
                lines.add(text.substring(start, i));
                if (c == '\r' && i + 1 < text.length() && text.charAt(i + 1) == '\n') {
                    i++;
                }
                start = i + 1;
            }
        }
        lines.add(text.substring(start));
        return lines;
    }

    private void write(TextLine line) throws IOException {
        out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
    }

    @Override
    public synchronized void applying(Input input, double simTime) {
        if (out == null) {
            return;
        }
        try {
            TextLine line = new TextLine(RecordingFormat.INPUT).integer(scheduler.modelTasksRun()).real(simTime);
            if (input instanceof ClientInput c) {
                int client = c.session().getNumber();
                if (clients.add(client)) {
                    write(new TextLine(RecordingFormat.CLIENT).integer(client).text(c.session().getDescription()));
                }
                InputText.write(line.integer(client), c.request());
            } else if (input instanceof ViewInput v) {
                InputText.write(line.integer(0), v.action());
            } else {
                throw new IllegalArgumentException("an input of unknown kind: " + input);
            }
            write(line);
        } catch (IOException | RuntimeException e) {
            breakOff("cannot record " + input + ": " + e.getMessage());
        }
    }

    /**
     * Stops recording with a line that says why, so a replay refuses the file with the reason; the
     * file keeps its {@code .part} name, as it is not a whole recording.
     */
    private void breakOff(String reason) {
        failure = "the recording " + fileName + " stops at " + scheduler.recordedTime() + " s: " + reason
                + "; what was recorded is in " + out.unfinished();
        log.logIt("X", "The recording " + fileName + " stops here: " + reason);
        try {
            write(new TextLine(RecordingFormat.BROKEN).text(reason));
        } catch (IOException e) {
            // The disk that refused the input refuses the note too; the failure is reported anyway.
        }
        out.abandon();
        out = null;
    }

    /** Puts everything recorded so far on disk; a failure breaks the recording off. Any thread. */
    public synchronized void flush() {
        if (out == null) {
            return;
        }
        try {
            out.flush();
        } catch (IOException e) {
            breakOff("cannot write: " + IoFailures.why(e));
        }
    }

    /** Why the recording is not whole (it broke off, or could not be finished), or null. */
    public synchronized String failure() {
        return failure;
    }

    /**
     * Writes the end of the run and closes the file. Call once the scheduler has stopped: the number of
     * model tasks run and the time are then final. If a task is still running (a robot's handler that
     * never returned), the run ends with the tasks that finished, and the events they sent: a replay
     * runs those and stops there.
     *
     * @param events what was sent to the clients, for the replay to check itself against
     */
    public synchronized void close(EventStream events) {
        if (out == null) {
            return;
        }
        try {
            long tasks = scheduler.modelTasksRun();
            long[] sent = scheduler.isIdle() ? new long[] {events.count(), events.checksum()} : events.before(tasks);
            write(new TextLine(RecordingFormat.END).integer(tasks).real(scheduler.recordedTime())
                    .word("events").integer(sent[0]).word("crc").word(Long.toHexString(sent[1])));
            out.finish();
        } catch (IOException e) {
            failure = "cannot finish the recording " + fileName + ": " + e.getMessage() + "; what reached the disk is in "
                    + out.unfinished();
            log.logIt("X", "C" + failure.substring(1));
            out.abandon();
        }
        out = null;
    }
}
