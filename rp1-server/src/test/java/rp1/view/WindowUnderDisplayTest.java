package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The real window, on a real display: {@code .ci/run} starts Xvfb when there is no display and
 * passes it as {@code -Drp1.display}. Without one this test fails, unless
 * {@code -Drp1.allowNoDisplay=true} is given to gradle (for developers without X), which skips it. The screenshot is left in {@code rp1-server/build/gui-test/window.png}.
 */
class WindowUnderDisplayTest {

    @Test
    @Timeout(240)
    void theWindowShowsTheWorldAndItsClicksReachTheSubscribedClient() throws Exception {
        String display = System.getenv("DISPLAY");
        if (display == null || display.isEmpty()) {
            if (Boolean.getBoolean("rp1.allowNoDisplay")) {
                Assumptions.abort("no DISPLAY; the window test is skipped because rp1.allowNoDisplay=true");
            }
            fail("No X display: DISPLAY is not set, so the window cannot be tested. .ci/run starts Xvfb for this; "
                    + "run it, or start Xvfb yourself (Xvfb :99 &) and run gradle test -Drp1.display=:99 (a Gradle "
                    + "daemon keeps the environment it was started with), or skip this test with "
                    + "gradle test -Drp1.allowNoDisplay=true");
        }
        Path out = Paths.get(System.getProperty("rp1.root", ".")).resolve("rp1-server/build/gui-test");
        ChildJvm.Result r = ChildJvm.run(WindowCheck.class.getName(), List.of(out.toString()), Map.of(), 180);
        assertEquals(0, r.exitCode(), "on DISPLAY=" + display + ":\n" + r.output());
        assertTrue(r.output().contains("WINDOW CHECK PASSED"), r.output());
        assertTrue(Files.size(out.resolve("window.png")) > 0);
    }
}
