package rp1demo.autopilot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsNavNode;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1demo.DemoRun;
import rp1demo.navigation.NavNetwork.Node;

/** The autopilot touring the contest arena's rooms along the navigation network. */
@Timeout(60)
class AutopilotTest {
    /** The shortest routes dock -> room1 -> room2 -> room3 -> room4 -> dock, node by node. */
    private static final List<String> EXPECTED = List.of(
            "hub", "hallW", "door1", "room1",
            "door1", "hallW", "hub", "hallS", "door2", "room2",
            "door2", "hallS", "hub", "hallN1", "hallN2", "door3", "room3",
            "door3", "hallN2", "hallN1", "door4", "room4",
            "door4", "hallN1", "hub", "dock");

    @Test
    void itVisitsEveryRoomByTheShortestRoutesAndComesHomeWithoutTouchingAWall() throws Exception {
        ApMain c = new ApMain();
        try (DemoRun run = DemoRun.start("contest.txt", c, c, c::getBody)) {
            run.waitUntil(() -> c.getTour() != null && c.getTour().isFinished(), 30, "the end of the tour");
            Tour tour = c.getTour();
            assertEquals(List.of("room1", "room2", "room3", "room4", "dock"), tour.visited());
            List<String> reached = new ArrayList<>();
            for (Node n : tour.reachedNodes()) {
                reached.add(n.name());
            }
            assertEquals(EXPECTED, reached, run.logText());

            List<RsMotionHaltedEvent> halts = run.events().events(RsMotionHaltedEvent.class);
            assertFalse(halts.stream().anyMatch(h -> h.causeOfHalt != RsMotionHaltedEvent.HALTED_ON_COMPLETION),
                    "every move completed; log:\n" + run.logText());
            RsPlacementEvent home = run.events().events(RsPlacementEvent.class).get(0);
            List<double[]> stops = distinctStops(home, halts);
            assertEquals(EXPECTED.size(), stops.size(), "one stop per node");
            for (int i = 0; i < EXPECTED.size(); i++) {
                RsNavNode node = (RsNavNode) run.simulation().getWorld().getPlan().getObjectByName(EXPECTED.get(i));
                double[] stop = stops.get(i);
                assertEquals(node.x, stop[0], 0.01, "stop " + i + " at " + node.getName());
                assertEquals(node.y, stop[1], 0.01, "stop " + i + " at " + node.getName());
            }
            assertTrue(run.simTime() < 200, "a tour of about 9 m and 25 turns, not " + run.simTime() + " s");
            assertFalse(run.robot().getTrails().isEmpty(), "the pen drew the route");
        }
    }

    /** Where the robot stood still between moves after leaving home, turns on the spot not counted. */
    private static List<double[]> distinctStops(RsPlacementEvent home, List<RsMotionHaltedEvent> halts) {
        List<double[]> stops = new ArrayList<>();
        double[] last = {home.x, home.y};
        for (RsMotionHaltedEvent h : halts) {
            if (Math.hypot(h.x - last[0], h.y - last[1]) > 0.005) {
                last = new double[] {h.x, h.y};
                stops.add(last);
            }
        }
        return stops;
    }
}
