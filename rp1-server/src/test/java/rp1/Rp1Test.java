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
}
