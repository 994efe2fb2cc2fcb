package rp1.simulator.record;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import rp1.io.IoFailures;
import rp1.simulator.world.WorldModel;

/**
 * Reads a recording (docs/recording.md) and checks it whole before anything is replayed: the format
 * and world-model versions, every line's fields, that inputs come in the order they were applied and
 * from clients that were introduced. Anything wrong is one {@link RecordingException} naming the file,
 * the line and what is wrong there.
 */
public final class RecordingReader {
    private final String file;
    private final List<String> lines;
    private int next;
    private long seed;
    private final Map<String, String> properties = new TreeMap<>();
    private String planName;
    private String planText;
    private final Map<Integer, String> clients = new HashMap<>();
    private final List<Recording.Step> steps = new ArrayList<>();
    private Recording.End end;
    private final int tornLine;

    private RecordingReader(String file, List<String> lines, int tornLine) {
        this.file = file;
        this.lines = lines;
        this.tornLine = tornLine;
    }

    /** Reads and checks the recording {@code path}. */
    public static Recording read(Path path) throws RecordingException {
        String text;
        try {
            if (Files.exists(path) && !Files.isRegularFile(path)) {
                throw new RecordingException(path + ": not a recording (not a file)");
            }
            long size = Files.size(path);
            // Read whole, the text takes about three times the file's size in memory as it is parsed.
            long most = Math.min(Integer.MAX_VALUE - 8, Runtime.getRuntime().maxMemory() / 4);
            if (size > most) {
                throw new RecordingException(path + ": the recording is " + size + " bytes, more than replay reads at"
                        + " once with this Java's heap (" + most + " bytes; a larger heap, RP1_OPTS=-Xmx8g, reads"
                        + " up to a quarter of it, at most 2 GB)");
            }
            text = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(Files.readAllBytes(path))).toString();
        } catch (CharacterCodingException e) {
            throw new RecordingException(path + ": not a recording (not UTF-8 text)");
        } catch (IOException e) {
            throw new RecordingException("cannot read the recording " + path + ": " + IoFailures.why(e), e);
        }
        return parse(path.toString(), text);
    }

    /**
     * Reads and checks a recording held in {@code text}; {@code file} names it in messages. A last line
     * without its line feed was cut off while being written (the run was killed) and is left out
     * ({@link Recording#tornLine()} says so).
     */
    public static Recording parse(String file, String text) throws RecordingException {
        if (text.isEmpty()) {
            throw new RecordingException(file + ": empty recording (the run was stopped before anything was written)");
        }
        List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
        String torn = lines.remove(lines.size() - 1);
        return new RecordingReader(file, lines, torn.isEmpty() ? 0 : lines.size() + 1).parse();
    }

    private Recording parse() throws RecordingException {
        header();
        for (LineCursor in = nextLine(); in != null; in = nextLine()) {
            if (end != null) {
                throw in.error("nothing may follow the end of the run (line " + end.line() + ")");
            }
            body(in);
        }
        return new Recording(file, seed, properties, planName, planText, clients, steps, end, tornLine);
    }

    /** The next line that is not a comment, or null at the end of the file. */
    private LineCursor nextLine() {
        while (next < lines.size()) {
            String text = lines.get(next++);
            if (!text.startsWith("#")) {
                return new LineCursor(file, next, text);
            }
        }
        return null;
    }

    private LineCursor cursor() throws RecordingException {
        LineCursor in = nextLine();
        if (in == null) {
            throw new RecordingException(file + ": the recording ends before its floor plan");
        }
        return in;
    }

    private void header() throws RecordingException {
        LineCursor in = nextLine();
        if (in == null || !in.word("the format name").equals(RecordingFormat.MAGIC)) {
            throw new RecordingException(file + ": not an RP1 recording (it must begin with \""
                    + RecordingFormat.MAGIC + " " + RecordingFormat.VERSION + "\")");
        }
        long version = in.integer("the format version");
        if (version != RecordingFormat.VERSION) {
            throw in.error("recording format version " + version + ", but this simulator reads version "
                    + RecordingFormat.VERSION + " only");
        }
        in.end();
        in = keyword(cursor(), RecordingFormat.WORLD_MODEL);
        long model = in.integer("the world-model version");
        in.end();
        if (model != WorldModel.VERSION) {
            throw in.error("recorded with world model " + model + ", but this simulator has world model "
                    + WorldModel.VERSION + ": the same inputs would give another run here; replay it with the"
                    + " simulator that recorded it");
        }
        in = keyword(cursor(), RecordingFormat.SEED);
        seed = in.integer("the seed");
        in.end();
        readProperties();
    }

    private static LineCursor keyword(LineCursor in, String expected) throws RecordingException {
        String w = in.word("\"" + expected + "\"");
        if (!w.equals(expected)) {
            throw in.error("\"" + expected + "\" was expected here, found \"" + w + "\"");
        }
        return in;
    }

    /** The property lines, then the plan line and the plan's text. */
    private void readProperties() throws RecordingException {
        while (true) {
            LineCursor in = cursor();
            String w = in.word("\"property\" or \"plan\"");
            if (w.equals(RecordingFormat.PLAN)) {
                readPlan(in);
                return;
            }
            if (!w.equals(RecordingFormat.PROPERTY)) {
                throw in.error("\"property\" or \"plan\" was expected here, found \"" + w + "\"");
            }
            String key = in.text("the property name");
            String value = in.text("the property value");
            in.end();
            if (key == null || value == null) {
                throw in.error("a property needs a name and a value");
            }
            properties.put(key, value);
        }
    }

    private void readPlan(LineCursor in) throws RecordingException {
        planName = in.text("the floor plan's name");
        long count = in.integer("the number of lines of the floor plan");
        in.end();
        if (count < 1 || count > lines.size() - next) {
            throw in.error("the floor plan is said to have " + count + " lines, but "
                    + (lines.size() - next) + " lines follow");
        }
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < count; i++) {
            String line = lines.get(next++);
            if (!line.startsWith(RecordingFormat.PLAN_LINE)) {
                throw new RecordingException(file + ":" + next + ": line " + (i + 1) + " of the floor plan must begin with \""
                        + RecordingFormat.PLAN_LINE + "\"");
            }
            if (i > 0) {
                text.append('\n');
            }
            text.append(line, RecordingFormat.PLAN_LINE.length(), line.length());
        }
        planText = text.toString();
    }

    /** A line after the plan: a client, an input, the end, or a note that the recording broke off. */
    private void body(LineCursor in) throws RecordingException {
        String w = in.word("a line kind");
        switch (w) {
            case RecordingFormat.CLIENT -> client(in);
            case RecordingFormat.INPUT -> input(in);
            case RecordingFormat.END -> end(in);
            case RecordingFormat.BROKEN -> throw in.error("the recording broke off here: " + in.text("the reason"));
            default -> throw in.error("unknown line kind \"" + w + "\" (client, input or end expected)");
        }
    }

    private void client(LineCursor in) throws RecordingException {
        int number = in.smallInteger("the client number");
        String description = in.text("the client's description");
        in.end();
        if (number < 1) {
            throw in.error("client numbers start at 1, found " + number);
        }
        if (clients.putIfAbsent(number, description == null ? "client " + number : description) != null) {
            throw in.error("client " + number + " is introduced twice");
        }
    }

    private void input(LineCursor in) throws RecordingException {
        long task = in.integer("the task number");
        double time = in.real("the time");
        int source = in.smallInteger("the source");
        checkOrder(in, task, time);
        if (source == 0) {
            steps.add(new Recording.Step(in.number(), task, time, 0, null, InputText.readViewAction(in)));
        } else if (clients.containsKey(source)) {
            steps.add(new Recording.Step(in.number(), task, time, source, InputText.readRequest(in), null));
        } else {
            throw in.error("an input from client " + source + ", which was not introduced by a client line");
        }
        in.end();
    }

    /** Inputs are applied in order: neither the task count nor the time goes back. */
    private void checkOrder(LineCursor in, long task, double time) throws RecordingException {
        if (task < 0 || !(time >= 0.0) || Double.isInfinite(time)) {
            throw in.error("the task number and time must be finite and not negative, found " + task + " and " + time);
        }
        if (!steps.isEmpty()) {
            Recording.Step last = steps.get(steps.size() - 1);
            if (task < last.task() || time < last.time()) {
                throw in.error("this input (after task " + task + ", at " + time + " s) comes before the one on line "
                        + last.line() + " (after task " + last.task() + ", at " + last.time() + " s)");
            }
        }
    }

    private void end(LineCursor in) throws RecordingException {
        long tasks = in.integer("the number of tasks run");
        double time = in.real("the end time");
        keyword(in, "events");
        long events = in.integer("the number of events");
        keyword(in, "crc");
        String crc = in.word("the events' CRC-32");
        in.end();
        long checksum;
        try {
            checksum = Long.parseLong(crc, 16);
        } catch (NumberFormatException e) {
            throw in.error("the events' CRC-32: a hexadecimal number was expected, found \"" + crc + "\"");
        }
        if (!steps.isEmpty() && tasks < steps.get(steps.size() - 1).task()) {
            throw in.error("the run is said to end after " + tasks + " tasks, before its last input (line "
                    + steps.get(steps.size() - 1).line() + ")");
        }
        end = new Recording.End(in.number(), tasks, time, events, checksum);
    }
}
