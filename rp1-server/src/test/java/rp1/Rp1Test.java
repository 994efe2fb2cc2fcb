package rp1;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** What the rp1 command makes of its command line and the display before the server starts. */
class Rp1Test {
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private List<String> serverArguments(Map<String, String> environment, String... args) throws Exception {
        return List.of(Rp1.serverArguments(args, environment, new PrintStream(err, true, StandardCharsets.UTF_8)));
    }

    @Test
    void aPropertiesFileIsHonouredWithoutADisplayAndRunsHeadless() throws Exception {
        assertEquals(List.of("-p", "mybot.ini", "--headless"), serverArguments(Map.of(), "-p", "mybot.ini"));
        assertEquals("", err.toString(StandardCharsets.UTF_8), "no word of a demo");
    }

    @Test
    void withoutAPropertiesFileOrADisplayTheHeadlessDemoRuns() throws Exception {
        assertEquals(List.of("--headless", "-p", Rp1.HEADLESS_DEMO), serverArguments(Map.of()));
        assertTrue(err.toString(StandardCharsets.UTF_8).startsWith("rp1: no display: the fire-fighting robot"));
    }

    @Test
    void headlessOnTheCommandLineOrInTheEnvironmentMeansNoWindowEvenWithADisplay() throws Exception {
        assertEquals(List.of("--headless", "-p", Rp1.HEADLESS_DEMO), serverArguments(Map.of("DISPLAY", "x:0"), "--headless"));
        assertEquals(List.of("-f", "WhiteRoom.txt", "--headless", "-p", Rp1.HEADLESS_DEMO),
                serverArguments(Map.of("RP1_HEADLESS", "1"), "-f", "WhiteRoom.txt"));
    }

    @Test
    void aDisplayNobodyAnswersOnIsNoDisplay() {
        assertFalse(Display.answers(null));
        assertFalse(Display.answers(""));
        assertFalse(Display.answers(":987"), "no X server on display 987");
        assertFalse(Display.answers("127.0.0.1:987"));
        assertTrue(Display.answers("/private/tmp/com.apple.launchd.x/org.xquartz:0"), "not understood: let the window try");
    }

    /** The options a usage lists in its option lines (those beginning with two spaces and a dash). */
    private static List<String> optionsListed(String usage) {
        return usage.lines().filter(l -> l.matches("  -[-a-z]+.*")).map(l -> l.trim().split("[ ,=]")[0]).toList();
    }

    @Test
    void rp1HelpNamesEveryOptionOfItsSweepAndReplay() {
        String sweep = Sweep.usage("rp1 sweep");
        String replay = Replay.usage("rp1 replay");
        for (String option : optionsListed(sweep)) {
            if (!option.equals("-h")) {
                assertTrue(Rp1.USAGE.contains(option), "rp1 --help leaves out rp1 sweep " + option + ":\n" + Rp1.USAGE);
            }
        }
        for (String option : optionsListed(replay)) {
            if (!option.equals("-h")) {
                assertTrue(Rp1.USAGE.contains(option), "rp1 --help leaves out rp1 replay " + option);
            }
        }
        assertTrue(optionsListed(sweep).containsAll(List.of("--vary", "--client", "--resume", "--html", "--master")),
                sweep);
    }

    @Test
    void aCommandMisspeltIsNamedAsMeantAndAnythingElseIsLeftToTheSimulator() {
        assertTrue(Rp1.misspeltCommand("swep").startsWith("rp1: unknown command swep; did you mean rp1 sweep?\nusage: rp1 "));
        assertTrue(Rp1.misspeltCommand("Replay").startsWith("rp1: unknown command Replay; did you mean rp1 replay?\n"));
        assertEquals(null, Rp1.misspeltCommand("-p"));
        assertEquals(null, Rp1.misspeltCommand("--headless"));
        assertEquals(null, Rp1.misspeltCommand("mybot.ini"), "no slip of a command: the simulator says what is wrong");
    }

    @Test
    void aSweepOrReplayStartedByRp1NamesItsCommandInItsUsage() {
        String sweep = Sweep.usage("rp1 sweep");
        assertTrue(sweep.startsWith("usage: rp1 sweep -p PROPERTIES"), sweep);
        // The synopsis's second line lines up under the first's options.
        assertEquals("usage: rp1 sweep ".length(), sweep.lines().skip(1).findFirst().orElseThrow().indexOf('['));
        List<String> lines = sweep.lines().toList();
        assertTrue(lines.get(lines.size() - 1).startsWith("  -h, --help"), "-h comes last:\n" + sweep);
        assertTrue(Replay.usage("rp1 replay").startsWith("usage: rp1 replay RECORDING"));
        assertTrue(Sweep.usage("java rp1.Sweep").startsWith("usage: java rp1.Sweep -p PROPERTIES"));
    }
}
