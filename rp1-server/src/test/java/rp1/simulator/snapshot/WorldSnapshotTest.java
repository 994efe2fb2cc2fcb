package rp1.simulator.snapshot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWheel;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.SimClock;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;

/** What a snapshot holds, and that it does not change when the world goes on. */
class WorldSnapshotTest {
    private final Scheduler scheduler = new Scheduler(SimClock.lockstep());
    private World world;
    private Robot robot;

    @BeforeEach
    void paintHalfAMetre() throws Exception {
        world = new World(SnapshotWorlds.whiteRoom(), scheduler, 0.05, new Random(1));
        robot = world.addRobot(SnapshotWorlds.paintingRobot(), SnapshotWorlds.IGNORE);
        scheduler.begin();
        SnapshotWorlds.paintForward(world, robot, 0.5, 0.0);
        scheduler.runUntilIdle();
    }

    @Test
    void aRobotIsItsPoseAndItsPartsInDrawingOrderWheelsAfterTheirWheelSystem() {
        RobotSnapshot r = WorldSnapshot.of(world, 1.0).robots().get(0);
        RsTransform pose = robot.pose();
        assertEquals(pose.m13, r.x());
        assertEquals(pose.m23, r.y());
        assertEquals(pose.getTheta(), r.theta());
        assertTrue(r.placed());
        assertEquals("painter", r.label());
        List<PartSnapshot> parts = r.parts();
        assertEquals(5, parts.size());
        assertTrue(parts.get(0).part() instanceof RsBodyCircle);
        assertTrue(parts.get(1).part() instanceof RsBodyPainter);
        assertTrue(parts.get(2).part() instanceof RsDifferentialSteering);
        assertTrue(parts.get(3).part() instanceof RsWheel);
        assertTrue(parts.get(4).part() instanceof RsWheel);
    }

    @Test
    void anActivePainterIsHotInTheSnapshotAndStaysSoAfterItStops() {
        WorldSnapshot s = WorldSnapshot.of(world, 1.0);
        assertTrue(s.robots().get(0).parts().get(1).hot());
        robot.getBody().getBodyPainterArray()[0].setHot(false);
        assertTrue(s.robots().get(0).parts().get(1).hot(), "a snapshot does not follow the live part");
        assertFalse(WorldSnapshot.of(world, 1.0).robots().get(0).parts().get(1).hot());
    }

    @Test
    void aTrailSnapshotKeepsItsPointsWhileTheTrailGrows() {
        WorldSnapshot before = WorldSnapshot.of(world, 1.0);
        TrailSnapshot trail = before.trails().get(0);
        int count = trail.count();
        double lastX = trail.x(count - 1);
        assertTrue(count > 10, "points every 2.5 cm over half a metre: " + count);
        SnapshotWorlds.paintForward(world, robot, 0.3, 1.0);
        scheduler.runUntilIdle();
        assertEquals(count, trail.count());
        assertEquals(lastX, trail.x(count - 1));
        assertTrue(trail.segment().getCount() > count, "the live segment went on");
        assertEquals(1, before.trails().size());
    }

    @Test
    void targetSelectionIsRecorded() {
        assertEquals(List.of(true), WorldSnapshot.of(world, 1.0).targetSelected());
        world.getPlan().processTargetSelectionRequest(1.0, new RsTargetSelectionRequest(false, "goal", false, false));
        assertFalse(WorldSnapshot.of(world, 1.0).isTargetSelected(0));
    }

    @Test
    void theTrailsOfADepartedRobotStayUntilTheTrailsAreRemoved() {
        world.removeRobot(robot);
        WorldSnapshot departed = WorldSnapshot.of(world, 1.0);
        assertTrue(departed.robots().isEmpty());
        assertEquals(1, departed.trails().size());
        world.removePaintTrails();
        assertTrue(WorldSnapshot.of(world, 1.0).trails().isEmpty());
    }

    @Test
    void thePlanAloneHasNoRobotsAndEveryTargetAsItIs() {
        WorldSnapshot s = WorldSnapshot.planOnly(world.getPlan());
        assertEquals(0.0, s.simTime());
        assertTrue(s.robots().isEmpty());
        assertTrue(s.trails().isEmpty());
        assertEquals(List.of(true), s.targetSelected());
    }
}
