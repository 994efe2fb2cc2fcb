package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsPlan;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.simulator.SimulationSettings;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;
import rp1.simulator.snapshot.SnapshotPublisher;

/**
 * The window's status line follows the simulation's clock, not the time of the last snapshot: while
 * a robot stands still no new snapshot is taken, yet time goes on (a user saw 0.051 s ten seconds
 * into a run). No display needed: the canvas and the status panel are driven without a frame.
 */
@Timeout(60)
class AnimationTest {
    private static final Pattern TIME = Pattern.compile("^t = (\\d+\\.\\d{3}) s");

    /** The parts of a window that one frame of animation updates. */
    private static final class Parts {
        final StatusPanel status;
        final PlanCanvas canvas;
        final Animation animation;

        Parts(Scenario s, SnapshotPublisher publisher) {
            RsPlan plan = s.simulation().getWorld().getPlan();
            status = new StatusPanel(DisplayUnits.of(plan.getUnits()));
            canvas = new PlanCanvas(new Renderer(plan), publisher.poll(), s.simulation(), p -> { });
            animation = new Animation(publisher, s.simulation()::getSimTime, canvas, status);
        }

        /** Connects ClientZero, places it at home and runs frames until the canvas shows it there. */
        ScenarioClient placeClientZero(Scenario s) throws InterruptedException {
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.sendPlacementRequest("home");
            c.await(RsPlacementEvent.class);
            while (canvas.shown().placedRobots().isEmpty()) {
                animation.frame();
                Thread.sleep(10);
            }
            return c;
        }
    }

    private static double shownTime(StatusPanel status) {
        Matcher m = TIME.matcher(status.stateText());
        assertTrue(m.find(), status.stateText());
        return Double.parseDouble(m.group(1));
    }

    @Test
    void theClockMovesOnWhileTheRobotStandsStill() throws Exception {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt");
             SnapshotPublisher publisher = new SnapshotPublisher(s.simulation())) {
            Parts window = new Parts(s, publisher);
            ScenarioClient c = window.placeClientZero(s);
            c.sendTimeoutRequest(2.0);
            c.await(RsTimeoutEvent.class);
            window.animation.frame();
            assertEquals("t = 2.000 s   ClientZero: x 2.500 m, y 2.500 m, heading 225.0 deg", window.status.stateText());
        }
    }

    @Test
    void atRealSpeedTheClockFollowsTheWallClockWhileNothingHappens() throws Exception {
        SimulationSettings paced = SimulationSettings.paced(0.05, 1.0, false, 1L);
        try (Scenario s = Scenario.with(Worlds.whiteRoomText(), paced);
             SnapshotPublisher publisher = new SnapshotPublisher(s.simulation())) {
            Parts window = new Parts(s, publisher);
            window.placeClientZero(s);
            window.animation.frame();
            double before = shownTime(window.status);
            Thread.sleep(500);
            window.animation.frame();
            double after = shownTime(window.status);
            assertTrue(after - before >= 0.4, "half a second of wall time at speed 1 moved the shown clock from "
                    + before + " to " + after + " s");
        }
    }
}
