package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import rp1.Replay;
import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsConnection;
import rp1.simulator.session.Request;
import rp1.simulator.world.WorldModel;

/** Reading recordings back: a sound one whole, a damaged one refused with the file, line and what is wrong. */
class RecordingReaderTest {
    private static final String FILE = "run.rec";

    @TempDir
    Path dir;

    /** A small sound recording; line 8 is the client, 9 and 10 its inputs, 11 the end. */
    private static String[] sound() {
        RsBody body = new RsBody("bot");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.1));
        String b64 = Base64.getEncoder().encodeToString(RsConnection.encodeBodySpecification(body));
        return new String[] {
            "rp1-recording 1",
            "world-model " + WorldModel.VERSION,
            "seed 7",
            "property \"floorPlanFileName\" \"room.txt\"",
            "plan \"room.txt\" 2",
            "|caption: \"room\";",
            "|placement p { geometry: 1, 1, 0; }",
            "client 1 \"client 1 (test)\"",
            "input 0 0.0 1 body " + b64,
            "input 0 0.0 1 placement \"p\"",
            "end 3 1.5 events 1 crc 1f",
        };
    }

    private static Recording parse(String... lines) throws RecordingException {
        return RecordingReader.parse(FILE, String.join("\n", lines) + "\n");
    }

    /** The sound recording with line {@code number} (from 1) replaced. */
    private static String[] replaced(int number, String line) {
        String[] lines = sound();
        lines[number - 1] = line;
        return lines;
    }

    @Test
    void aSoundRecordingIsReadWhole() throws Exception {
        Recording r = parse(sound());
        assertEquals(7, r.seed());
        assertEquals("room.txt", r.properties().get("floorPlanFileName"));
        assertEquals("caption: \"room\";\nplacement p { geometry: 1, 1, 0; }", r.planText());
        assertEquals("client 1 (test)", r.clients().get(1));
        assertEquals(2, r.steps().size());
        assertEquals(new Request.Placement("p"), r.steps().get(1).request());
        assertEquals(10, r.steps().get(1).line());
        assertEquals(new Recording.End(11, 3, 1.5, 1, 0x1f), r.end());
    }

    @Test
    void aFolderOrAFileTooLargeToReadIsRefusedWithAMessageNotRunOutOfMemoryOver(@TempDir Path dir) throws Exception {
        RecordingException folder = assertThrows(RecordingException.class, () -> RecordingReader.read(dir));
        assertEquals(dir + ": not a recording (not a file)", folder.getMessage());
        Path huge = dir.resolve("huge.rec");
        try (RandomAccessFile f = new RandomAccessFile(huge.toFile(), "rw")) {
            f.setLength(3L << 30); // sparse: no disk is used
        }
        RecordingException large = assertThrows(RecordingException.class, () -> RecordingReader.read(huge));
        assertTrue(large.getMessage().startsWith(huge + ": the recording is 3221225472 bytes, more than replay reads"
                + " at once with this Java's heap ("), large.getMessage());
    }

    @Test
    void commentsMayStandAnywhereAfterTheHeaderEvenLast() throws Exception {
        String[] lines = sound();
        String[] commented = new String[lines.length + 2];
        System.arraycopy(lines, 0, commented, 0, 9);
        commented[9] = "# a note between two inputs";
        System.arraycopy(lines, 9, commented, 10, lines.length - 9);
        commented[commented.length - 1] = "# a note after the end";
        Recording r = parse(commented);
        assertEquals(2, r.steps().size());
        assertEquals(3, r.end().tasks());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "9 | input x 0.0 1 halt | run.rec:9: the task number: an integer was expected, found \"x\"",
        "9 | input 0 0.0 2 halt | run.rec:9: an input from client 2, which was not introduced by a client line",
        "9 | input 0 0.0 1 fly | run.rec:9: unknown request \"fly\"",
        "9 | input 0 0.0 1 body AAAA | run.rec:9: the body specification is damaged",
        "9 | input 0 0.0 1 body ??? | run.rec:9: the body specification is not valid Base64",
        "10 | input 0 0.0 1 placement \"p | run.rec:10: placement name: the closing quote is missing",
        "10 | input 0 0.0 1 placement \"p\" 3 | run.rec:10: unexpected text at the end of the line: \"3\"",
        "10 | 'input 0 0.0 1 halt ' | run.rec:10: the line ends with a space after the kind of request",
        "11 | input 0 -1.0 1 halt | run.rec:11: the task number and time must be finite and not negative",
        "11 | end 3 1.5 events 1 | run.rec:11: the line ends where \"crc\" was expected",
        "11 | broken \"cannot write\" | run.rec:11: the recording broke off here: cannot write",
        "5 | plan \"room.txt\" 9 | run.rec:5: the floor plan is said to have 9 lines, but",
        "7 | placement p { geometry: 1, 1, 0; } | run.rec:7: line 2 of the floor plan must begin with \"|\"",
        "3 | seed many | run.rec:3: the seed: an integer was expected, found \"many\"",
    })
    void aDamagedRecordingIsRefusedNamingTheLineAndWhatIsWrong(int line, String text, String message) {
        RecordingException e = assertThrows(RecordingException.class, () -> parse(replaced(line, text)));
        assertTrue(e.getMessage().startsWith(message), e.getMessage());
    }

    @Test
    void aNumberThatIsNotFiniteIsRefusedAtItsLine() {
        // Nothing on the wire can be NaN or infinite: such a recording was edited, and replayed to the end
        // only to say it differed from the recorded run.
        RecordingException e = assertThrows(RecordingException.class,
                () -> parse(replaced(10, "input 0 0.0 1 motion 0.5 NaN 2.0")));
        assertEquals("run.rec:10: rotational velocity: a finite number was expected, found NaN", e.getMessage());
        assertThrows(RecordingException.class, () -> parse(replaced(10, "input 0 0.0 1 heartbeat Infinity")));
        assertThrows(RecordingException.class, () -> parse(replaced(10, "input 0 0.0 1 heartbeat 1e999")));
    }

    @Test
    void inputsOutOfOrderAreRefused() {
        String[] lines = replaced(10, "input 0 0.0 1 halt");
        lines[8] = "input 2 0.5 1 position";
        RecordingException e = assertThrows(RecordingException.class, () -> parse(lines));
        assertTrue(e.getMessage().startsWith("run.rec:10: this input (after task 0, at 0.0 s) comes before the one on"
                + " line 9"), e.getMessage());
    }

    @Test
    void aRecordingOfAnotherWorldModelIsRefusedSayingWhichModelsDiffer() {
        RecordingException e = assertThrows(RecordingException.class,
                () -> parse(replaced(2, "world-model " + (WorldModel.VERSION + 1))));
        assertEquals("run.rec:2: recorded with world model " + (WorldModel.VERSION + 1) + ", but this simulator has"
                + " world model " + WorldModel.VERSION + ": the same inputs would give another run here; replay it"
                + " with the simulator that recorded it", e.getMessage());
    }

    @Test
    void aRecordingOfAnotherFormatVersionIsRefused() {
        RecordingException e = assertThrows(RecordingException.class, () -> parse(replaced(1, "rp1-recording 0")));
        assertEquals("run.rec:1: recording format version 0, but this simulator reads version 1 only", e.getMessage());
    }

    @Test
    void aFileThatIsNoRecordingIsRefused() {
        RecordingException e = assertThrows(RecordingException.class, () -> parse("caption: \"a floor plan\";"));
        assertEquals("run.rec: not an RP1 recording (it must begin with \"rp1-recording 1\")", e.getMessage());
    }

    @Test
    void aRecordingCutOffInTheMiddleOfALineIsReadUpToItsLastWholeLine() throws Exception {
        String[] lines = sound();
        String text = String.join("\n", lines);
        Recording r = RecordingReader.parse(FILE, text.substring(0, text.length() - 8));
        assertNull(r.end(), "a run that was killed has no end");
        assertEquals(2, r.steps().size());
        assertEquals(11, r.tornLine(), "the line left out is named");
        assertEquals(0, parse(sound()).tornLine());
    }

    @Test
    void anEmptyFileIsRefusedSayingTheRunWasStoppedBeforeAnythingWasWritten() {
        RecordingException e = assertThrows(RecordingException.class, () -> RecordingReader.parse(FILE, ""));
        assertEquals("run.rec: empty recording (the run was stopped before anything was written)", e.getMessage());
    }

    @Test
    void theReplayOfARecordingWithoutItsEndSaysItIsPartialAndWhichLineWasLeftOut() throws Exception {
        String text = String.join("\n", replaced(7, "|placement p { geometry: 1, 1, 0, 0.2; }"));
        Path file = dir.resolve(FILE);
        Files.write(file, text.substring(0, text.length() - 8).getBytes(StandardCharsets.UTF_8));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {file.toString()}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(Replay.PARTIAL, status, err.toString(StandardCharsets.UTF_8));
        String[] lines = err.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals("rp1.Replay: " + file + ":11: the last line was cut off while it was being written (the run was"
                + " killed); it is left out", lines[0]);
        assertTrue(lines[1].startsWith("rp1.Replay: partial recording: " + file + " ends at t=0.0 s (it has no end line:"
                + " the run did not stop cleanly); replayed as far as it goes: "), lines[1]);
    }

    @Test
    void theReplayCommandRefusesADamagedRecordingWithItsMessageAndStatusOne() throws Exception {
        Path file = dir.resolve(FILE);
        Files.write(file, (String.join("\n", replaced(10, "input 0 0.0 1 placement p")) + "\n")
                .getBytes(StandardCharsets.UTF_8));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {file.toString()}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertEquals("rp1.Replay: " + file + ":10: placement name: quoted text was expected\n",
                err.toString(StandardCharsets.UTF_8));
    }
}
