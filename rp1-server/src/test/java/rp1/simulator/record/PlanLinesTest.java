package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/** A recording's plan lines: the plan's text cut at any line ending, as a reader puts it back together. */
class PlanLinesTest {
    @Test
    void cutsAtEveryKindOfLineEnding() {
        assertEquals(List.of("wall a", "wall b", "wall c", "end"), Recorder.lines("wall a\r\nwall b\rwall c\nend"));
    }

    @Test
    void keepsEmptyLinesFirstAndLast() {
        assertEquals(List.of(""), Recorder.lines(""));
        assertEquals(List.of("", "units meters;", ""), Recorder.lines("\nunits meters;\n"));
        assertEquals(List.of("a", "", "b"), Recorder.lines("a\n\rb"), "\\n then \\r are two line endings");
        assertEquals(List.of("a", "", ""), Recorder.lines("a\r\n\r\n"));
    }

    /** The lines are the ones recordings have always had (they were cut with this expression). */
    @Test
    void theSameLinesAsTheRegularExpressionGave() {
        Pattern lineBreak = Pattern.compile("\r\n|\r|\n");
        String[] pieces = {"", "x", "\n", "\r", "\r\n", "\n\r", "yz"};
        java.util.Random random = new java.util.Random(7);
        for (int trial = 0; trial < 2000; trial++) {
            StringBuilder text = new StringBuilder();
            for (int k = random.nextInt(8); k > 0; k--) {
                text.append(pieces[random.nextInt(pieces.length)]);
            }
            String t = text.toString();
            assertEquals(List.of(lineBreak.split(t, -1)), Recorder.lines(t), () -> "for " + t.replace("\r", "\\r").replace("\n", "\\n"));
        }
    }
}
