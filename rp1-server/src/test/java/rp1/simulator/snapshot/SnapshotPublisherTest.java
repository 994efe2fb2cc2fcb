package rp1.simulator.snapshot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import rp1.rossum.RsLogger;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;

/** The publisher takes a snapshot only when it is polled and the world changed. */
class SnapshotPublisherTest {
    private Simulation simulation;
    private Scheduler scheduler;
    private World world;

    @BeforeEach
    void lockstepWhiteRoom() throws Exception {
        simulation = new Simulation(SnapshotWorlds.whiteRoom(), SimulationSettings.lockstep(0.05, 1L), new RsLogger(null, false));
        scheduler = simulation.getScheduler();
        world = simulation.getWorld();
        scheduler.begin();
    }

    @Test
    void atFirstItShowsThePlanAlone() {
        try (SnapshotPublisher p = new SnapshotPublisher(simulation)) {
            WorldSnapshot s = p.poll();
            assertSame(world.getPlan(), s.plan());
            assertTrue(s.robots().isEmpty());
        }
    }

    @Test
    void aPollAfterAChangeQueuesOneCaptureAndALaterPollReturnsIt() {
        try (SnapshotPublisher p = new SnapshotPublisher(simulation)) {
            Robot r = world.addRobot(SnapshotWorlds.paintingRobot(), SnapshotWorlds.IGNORE);
            world.place(r, "home", 0.0);
            scheduler.runUntilIdle();
            WorldSnapshot stale = p.poll();
            p.poll();
            assertEquals(1, scheduler.size(), "one capture, however often it is polled");
            scheduler.runUntilIdle();
            WorldSnapshot fresh = p.poll();
            assertNotSame(stale, fresh);
            assertTrue(fresh.robots().get(0).placed());
        }
    }

    @Test
    void pollingAnUnchangedWorldCostsTheSimulationNothing() {
        try (SnapshotPublisher p = new SnapshotPublisher(simulation)) {
            p.poll();
            scheduler.runUntilIdle();
            WorldSnapshot s = p.poll();
            for (int i = 0; i < 100; i++) {
                assertSame(s, p.poll());
            }
            assertEquals(0, scheduler.size());
        }
    }

    @Test
    void theSnapshotIsStampedWithTheTimeTheCaptureRanAt() {
        try (SnapshotPublisher p = new SnapshotPublisher(simulation)) {
            Robot r = world.addRobot(SnapshotWorlds.paintingRobot(), SnapshotWorlds.IGNORE);
            SnapshotWorlds.paintForward(world, r, 0.5, 0.0);
            scheduler.runUntilIdle();
            p.poll();
            scheduler.runUntilIdle();
            WorldSnapshot s = p.poll();
            assertEquals(1.0, s.simTime(), 1e-12, "the clock stands at the end of the motion");
            assertEquals(r.pose().m13, s.robots().get(0).x());
        }
    }

    @Test
    void closingStopsObservingAndWithdrawsAQueuedCapture() {
        SnapshotPublisher p = new SnapshotPublisher(simulation);
        p.poll();
        assertEquals(1, scheduler.size());
        p.close();
        assertEquals(0, scheduler.size());
        world.changed(Double.NaN);
        WorldSnapshot last = p.poll();
        scheduler.runUntilIdle();
        assertSame(last, p.poll(), "a closed publisher takes no more snapshots");
    }
}
