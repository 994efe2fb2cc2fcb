package rp1demo.clientzero;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1demo.DemoRun;
import rp1demo.navigation.Pose;

/**
 * ClientZero in the White Room (home at (2.5, 2.5) facing 225 degrees, walls on the square
 * (0,0)-(3,3), 5 cm thick), steered by clicks injected as the simulator's view would send them.
 */
@Timeout(60)
class ClientZeroTest {
    private static final double EAST_WALL_INSIDE = 3.0 - 0.025;

    private static DemoRun start(ClnMain c) throws Exception {
        return DemoRun.start("WhiteRoom.txt", c, c, c::getBody);
    }

    private static RsMotionHaltedEvent haltAfter(DemoRun run, double time) throws InterruptedException {
        return run.events().await(RsMotionHaltedEvent.class, e -> e.simTime > time, 20);
    }

    @Test
    void aLeftClickTakesItToThePointAndAClickBeyondAWallEndsInACollisionAndABackOff() throws Exception {
        ClnMain c = new ClnMain();
        try (DemoRun run = start(c)) {
            RsPlacementEvent placed = run.events().await(RsPlacementEvent.class, e -> true, 20);
            assertTrue(placed.valid, run.logText());
            assertEquals(2.5, placed.x, 1e-12);

            run.simulation().mouseClick(0, 1, 2.3, 1.6);
            RsMotionHaltedEvent arrived = haltAfter(run, 0.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, arrived.causeOfHalt, run.logText());
            assertEquals(2.3, arrived.x, 0.005, "ends on the clicked point");
            assertEquals(1.6, arrived.y, 0.005, "ends on the clicked point");

            run.simulation().mouseClick(0, 1, 3.5, 1.6);
            RsMotionHaltedEvent bumped = haltAfter(run, arrived.simTime);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, bumped.causeOfHalt, run.logText());
            assertTrue(bumped.x + ClientZero.RADIUS <= EAST_WALL_INSIDE + 1e-9, "stopped short of the east wall");
            assertTrue(bumped.x > EAST_WALL_INSIDE - ClientZero.HEAD_X - 0.01, "stopped at the east wall, x = " + bumped.x);

            RsMotionHaltedEvent backedOff = haltAfter(run, bumped.simTime);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, backedOff.causeOfHalt);
            assertEquals(ClnNavigator.BACK_OFF_DISTANCE, Math.hypot(backedOff.x - bumped.x, backedOff.y - bumped.y), 1e-6);
            assertTrue(backedOff.x < bumped.x, "backed away from the wall");
            assertEquals(backedOff.simTime - bumped.simTime,
                    ClnMain.BACK_OFF_DELAY + ClnNavigator.BACK_OFF_DISTANCE / ClnMain.BACK_OFF_SPEED, 1e-6);
        }
    }

    @Test
    void aRightClickTurnsItOnTheSpotToFaceThePoint() throws Exception {
        ClnMain c = new ClnMain();
        try (DemoRun run = start(c)) {
            run.events().await(RsPlacementEvent.class, e -> e.valid, 20);
            run.simulation().mouseClick(1, 1, 2.5, 0.5);
            RsMotionHaltedEvent turned = haltAfter(run, 0.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, turned.causeOfHalt);
            assertEquals(2.5, turned.x, 1e-9, "turned on the spot");
            assertEquals(2.5, turned.y, 1e-9, "turned on the spot");
            assertEquals(-Math.PI / 2, Pose.normalize(turned.orientation), 1e-3, "faces the point, due south");
        }
    }

    @Test
    void itBuildsTheNavigationNetworkOfTheContestArenaFromThePlanEvent() throws Exception {
        ClnMain c = new ClnMain();
        try (DemoRun run = DemoRun.start("contest.txt", c, c, c::getBody)) {
            run.events().await(RsPlacementEvent.class, e -> true, 20);
            run.waitUntil(() -> c.getNavNetwork() != null, 10, "the plan event");
            assertEquals(14, c.getNavNetwork().nodeCount());
            assertEquals(13, c.getNavNetwork().linkCount());
            List<?> rooms = c.getNavNetwork().deadEnds();
            assertEquals(5, rooms.size(), "four rooms and the dock");
            assertNotNull(c.getNavNetwork().node("hub"));
        }
    }
}
