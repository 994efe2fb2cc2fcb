package rp1.view;

import java.util.List;

import rp1.rossum.event.RsTimeoutEvent;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;

/**
 * Run in a JVM that may open windows, with DISPLAY naming a display that does not exist: the view
 * logs one line and the simulation runs on.
 */
public final class UnreachableDisplayCheck {
    private UnreachableDisplayCheck() {
    }

    public static void main(String[] args) {
        ChildCheck.run("UNREACHABLE DISPLAY CHECK", UnreachableDisplayCheck::check);
    }

    private static Void check() throws Exception {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            Worlds.RecordingLog log = new Worlds.RecordingLog();
            RunningView view = ViewLauncher.start(s.simulation(), Worlds.config(), log, () -> { });
            if (view.hasWindow()) {
                throw new AssertionError("a window opened on DISPLAY=" + System.getenv("DISPLAY"));
            }
            List<String> lines = log.lines();
            if (lines.size() != 2 || !lines.get(1).startsWith("s GUI not available (")) {
                throw new AssertionError("expected \"Starting GUI\" and one line saying why not, got " + lines);
            }
            System.out.println("logged: " + lines.get(1));
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.sendPlacementRequest("home"); // at max speed, time passes only while a robot is on the floor
            c.sendTimeoutRequest(2.0);
            c.await(RsTimeoutEvent.class);
            view.close();
        }
        return null;
    }
}
