package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The real window, on a real display: the one {@code DISPLAY} names, or else a virtual display (Xvfb)
 * the test starts and stops itself. With neither, the test is reported as skipped with the reason.
 * The screenshot is left in {@code rp1-server/build/gui-test/window.png}, Xvfb's messages in
 * {@code xvfb.log} beside it.
 */
class WindowUnderDisplayTest {

    @Test
    @Timeout(240)
    void theWindowShowsTheWorldAndItsClicksReachTheSubscribedClient() throws Exception {
        Path out = Paths.get(System.getProperty("rp1.root", ".")).resolve("rp1-server/build/gui-test");
        try (TestDisplay display = TestDisplay.openOrSkip(out.resolve("xvfb.log"))) {
            Files.deleteIfExists(out.resolve("window.png"));
            ChildJvm.Result r = ChildJvm.run(WindowCheck.class.getName(), List.of(out.toString()),
                    Map.of("DISPLAY", display.name()), 180);
            String where = "on DISPLAY=" + display.name() + (display.isVirtual() ? " (Xvfb started by the test)"
                    : " (from the environment; a Gradle daemon keeps the one it was started with)");
            assertEquals(0, r.exitCode(), where + ":\n" + r.output());
            assertTrue(r.output().contains("WINDOW CHECK PASSED"), where + ":\n" + r.output());
            assertTrue(Files.size(out.resolve("window.png")) > 0);
        }
    }
}
