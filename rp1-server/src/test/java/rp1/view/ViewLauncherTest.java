package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsTimeoutEvent;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;

/** Without a display, or with the GUI disabled, the view says so in one line and the simulation runs on. */
@Timeout(120)
class ViewLauncherTest {

    private static List<String> launch(String... keysAndValues) throws Exception {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            Worlds.RecordingLog log = new Worlds.RecordingLog();
            RunningView view = ViewLauncher.start(s.simulation(), Worlds.config(keysAndValues), log, () -> { });
            assertFalse(view.hasWindow());
            assertFalse(view.writesPictures());
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.sendPlacementRequest("home"); // at max speed, time passes only while a robot is on the floor
            c.sendTimeoutRequest(1.0);
            assertEquals(1.0, c.await(RsTimeoutEvent.class).simTime, "the simulation runs on");
            view.close();
            return log.lines();
        }
    }

    @Test
    void withTheGuiEnabledButNoDisplayOneLineSaysSo() throws Exception {
        assertFalse(ViewLauncher.displayAvailable(), "the tests run with java.awt.headless=true");
        assertEquals(List.of("s GUI not available (no display: DISPLAY is not set or java.awt.headless=true); running headless"),
                launch());
    }

    @Test
    void withTheGuiDisabledTheOriginalsLineIsLogged() throws Exception {
        assertEquals(List.of("s GUI is disabled (in response to configuration option)"), launch("enableGUI", "false"));
    }

    @Test
    void aDisplayThatCannotBeOpenedIsNoCrashEither() throws Exception {
        ChildJvm.Result r = ChildJvm.run(UnreachableDisplayCheck.class.getName(), List.of(),
                Map.of("DISPLAY", ":4711"), 90);
        assertEquals(0, r.exitCode(), r.output());
        assertTrue(r.output().contains("UNREACHABLE DISPLAY CHECK PASSED"), r.output());
    }
}
