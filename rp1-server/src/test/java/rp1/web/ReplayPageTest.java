package rp1.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;

/**
 * {@code rp1.Replay --html}: one page that holds the run, gathered by an observer that leaves the
 * replay's events as they are.
 */
@Timeout(120)
class ReplayPageTest {
    @TempDir
    static Path dir;
    static Path recording;

    @BeforeAll
    static void record() throws Exception {
        recording = Runs.record(dir, 20.0);
    }

    private static int replay(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Replay.run(args, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertEquals(0, status, err.toString(StandardCharsets.UTF_8));
        return status;
    }

    private static String text(Path p) throws Exception {
        return Files.readString(p, StandardCharsets.UTF_8);
    }

    @Test
    void writingThePageLeavesTheEventLogAsTheRunWroteIt() throws Exception {
        replay(recording.toString(), "--events", dir.resolve("plain.events").toString());
        replay(recording.toString(), "--events", dir.resolve("paged.events").toString(), "--html",
                dir.resolve("paged.html").toString());
        String run = text(dir.resolve("run.events"));
        assertTrue(run.contains(" RangeSensor ") && run.contains(" MotionHalted "), "the run senses and moves:\n" + run);
        assertEquals(run, text(dir.resolve("plain.events")));
        assertEquals(run, text(dir.resolve("paged.events")));
    }

    @Test
    void aRobotWhoseClientLeftIsOffTheFloorFromThen(@TempDir Path left) throws Exception {
        Path run = Runs.record(left, 20.0, "dlcName=" + Leaver.class.getName(), "exitWhenClientsDone=false");
        Path page = left.resolve("left.html");
        replay(run.toString(), "--html", page.toString());
        Matcher placed = Pattern.compile("\"pl\":\\[([0-9,]*)\\]").matcher(text(page));
        assertTrue(placed.find(), "the robot's change list of being on the floor");
        String[] changes = placed.group(1).split(",");
        assertEquals(4, changes.length, "placed once, then gone: " + placed.group(1));
        assertEquals(List.of("1", "0"), List.of(changes[1], changes[3]));
    }

    @Test
    void thePageIsOneFileThatFetchesNothingAndHoldsEveryEvent() throws Exception {
        Path page = dir.resolve("page.html");
        replay(recording.toString(), "--html", page.toString());
        String html = text(page);
        for (String outside : List.of("src=", "http://", "https://", "url(", "@import", "fetch(\"http")) {
            assertFalse(html.contains(outside), "the page refers to something outside it: " + outside);
        }
        assertFalse(Pattern.compile("href=\"(?!data:)").matcher(html).find(), "the page links to nothing outside it");
        assertTrue(html.contains("\"name\":\"Wanderer\""), "the robot is in the page");
        List<String> events = Files.readAllLines(dir.resolve("run.events"), StandardCharsets.UTF_8);
        String last = events.get(events.size() - 1).replace("\\", "\\\\").replace("\"", "\\\"");
        assertTrue(html.contains("\"" + last + "\""), "the last event is listed: " + last);
        assertEquals(events.size() - 1, Pattern.compile("\"[0-9.E-]+ 1 [A-Za-z]+ [^\"]*\"").matcher(html).results().count()
                + Pattern.compile("\"[0-9.E-]+ 1 [A-Za-z]+\"").matcher(html).results().count(), "one entry per event");
    }
}
