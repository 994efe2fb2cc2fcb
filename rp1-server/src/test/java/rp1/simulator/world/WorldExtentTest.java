package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;
import rp1.rossum.event.RsPlacementEvent;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.SimClock;

/**
 * A plan built in code is not checked by the parser: a world over one of absurd extent still builds
 * its indexes in bounded memory and places robots at both ends of it.
 */
class WorldExtentTest {
    private static final double FAR = 1e300;

    private static RsPlan planReachingFar() {
        RsPlan plan = new RsPlan("far");
        for (int i = 0; i < 30; i++) {
            RsWall w = new RsWall("w" + i, plan);
            w.setGeometry(new double[] {i, 0, i, 3, 0.05});
            plan.addObject(w);
        }
        RsWall farWall = new RsWall("farWall", plan);
        farWall.setGeometry(new double[] {FAR, 0, FAR, 3, 0.05});
        plan.addObject(farWall);
        plan.addObject(placement(plan, "home", 0.5, 1.5));
        plan.addObject(placement(plan, "far", FAR - 1, 1.5));
        return plan;
    }

    private static RsPlacement placement(RsPlan plan, String name, double x, double y) {
        RsPlacement p = new RsPlacement(name, plan);
        p.setGeometry(new double[] {x, y, 0, 0.1});
        return p;
    }

    @Test
    void aWorldOfHugeExtentBuildsAndPlacesRobotsAtBothEnds() {
        World w = new World(planReachingFar(), new Scheduler(SimClock.lockstep()), 0.05, new Random(1));
        WorldPlacementTest.Inbox inbox = new WorldPlacementTest.Inbox();
        RsBody body = new RsBody("r");
        body.addPart(new RsBodyCircle(0, 0, 0.15));
        w.place(w.addRobot(body, inbox), "far", 0.0);
        w.place(w.addRobot(body, inbox), "home", 0.0);
        assertTrue(((RsPlacementEvent) inbox.events.get(0)).valid, "placed far away");
        assertTrue(inbox.lastPlacement().valid, "placed at home");
    }
}
