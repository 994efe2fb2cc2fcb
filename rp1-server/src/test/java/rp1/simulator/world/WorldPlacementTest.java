package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.SimClock;

/** Placements by name, at random, at a random pose, and their refusals (behavior.md section 7). */
class WorldPlacementTest {
    private static final String ROOM = String.join("\n",
        "wall s { geometry: 0, 0, 4, 0, 0.02; }",
        "wall n { geometry: 0, 4, 4, 4, 0.02; }",
        "wall w { geometry: 0, 0, 0, 4, 0.02; }",
        "wall e { geometry: 4, 0, 4, 4, 0.02; }",
        "obstacle block { geometry: 1.5, 1.5, 2.5, 1.5, 2.5, 2.5, 1.5, 2.5; }",
        "placement a { geometry: 0.5, 0.5, 45, 0.1; }",
        "placement b { geometry: 3.5, 3.5, 225, 0.1; }",
        "placement inBlock { geometry: 2, 2, 0, 0.1; }",
        "");

    private final Scheduler scheduler = new Scheduler(SimClock.lockstep());

    private World world(long seed) throws Exception {
        RsPlan plan = RsPlanParser.parse(ROOM, "room");
        return new World(plan, scheduler, 0.05, new Random(seed));
    }

    private static RsBody round(String name) {
        RsBody b = new RsBody(name);
        b.addPart(new RsBodyCircle(0, 0, 0.15));
        return b;
    }

    /** Collects what a robot is sent. */
    static final class Inbox implements EventSink {
        final List<RsEvent> events = new ArrayList<>();

        @Override
        public void send(RsEvent event) {
            events.add(event);
        }

        @Override
        public boolean isSubscribed(int eventCode, int index) {
            return true;
        }

        RsPlacementEvent lastPlacement() {
            return (RsPlacementEvent) events.get(events.size() - 1);
        }
    }

    @Test
    void aNamedPlacementPutsTheRobotExactlyThereWithTheOrientationAsStored() throws Exception {
        World w = world(1);
        Inbox in = new Inbox();
        Robot r = w.addRobot(round("r"), in);
        w.place(r, "b", 0.5);
        RsPlacementEvent e = in.lastPlacement();
        assertTrue(e.valid);
        assertEquals("b", e.name);
        assertEquals(3.5, e.x);
        assertEquals(225 * Math.PI / 180, e.orientation, "not normalized");
        assertEquals(0.5, e.simTime);
        assertTrue(r.isPlaced());
    }

    @Test
    void aPlacementOverlappingAnObstacleOrAnUnknownNameIsInvalid() throws Exception {
        World w = world(1);
        Inbox in = new Inbox();
        Robot r = w.addRobot(round("r"), in);
        w.place(r, "inBlock", 0.0);
        assertFalse(in.lastPlacement().valid);
        assertEquals("inBlock", in.lastPlacement().name);
        w.place(r, "nowhere", 0.0);
        assertFalse(in.lastPlacement().valid);
        assertEquals(0.0, in.lastPlacement().x);
        assertFalse(r.isPlaced());
    }

    @Test
    void aRefusalSaysWhyForTheServersLog() throws Exception {
        World w = world(1);
        Robot first = w.addRobot(round("first"), new Inbox());
        Robot second = w.addRobot(round("second"), new Inbox());
        assertEquals(null, w.place(first, "a", 0.0), "placed");
        assertEquals("another robot is in the way", w.place(second, "a", 0.0));
        assertEquals("a wall is in the way", w.place(second, "inBlock", 0.0));
        assertEquals("the floor plan has no placement of that name", w.place(second, "nowhere", 0.0));
        assertEquals("the floor plan has no placement of that name", w.place(second, "block", 0.0),
                "an obstacle's name is not a placement's");
        w.place(second, "b", 0.0);
        Robot third = w.addRobot(round("third"), new Inbox());
        assertEquals("every placement of the floor plan is taken or blocked", w.place(third, "", 0.0));
    }

    @Test
    void aNamelessPlacementPicksAClearPlacementAtRandom() throws Exception {
        for (long seed = 0; seed < 20; seed++) {
            World w = world(seed);
            Inbox in = new Inbox();
            w.place(w.addRobot(round("r"), in), null, 0.0);
            assertTrue(in.lastPlacement().valid);
            assertTrue(in.lastPlacement().name.equals("a") || in.lastPlacement().name.equals("b"), "never the blocked one");
        }
    }

    @Test
    void aRandomPoseIsClearOfWallsAndTheSameForTheSameSeed() throws Exception {
        double[] xs = new double[2];
        for (int run = 0; run < 2; run++) {
            World w = world(42);
            Inbox in = new Inbox();
            w.place(w.addRobot(round("r"), in), "$random", 0.0);
            RsPlacementEvent e = in.lastPlacement();
            assertTrue(e.valid);
            assertEquals("$random", e.name);
            assertFalse(Math.abs(e.x - 2) < 0.65 && Math.abs(e.y - 2) < 0.65, "not inside the block");
            xs[run] = e.x;
        }
        assertEquals(xs[0], xs[1]);
    }

    @Test
    void aSecondRobotCannotBePlacedOnTheFirstButElsewhereItCan() throws Exception {
        World w = world(1);
        Inbox ia = new Inbox();
        Inbox ib = new Inbox();
        Robot a = w.addRobot(round("a"), ia);
        Robot b = w.addRobot(round("b"), ib);
        w.place(a, "a", 0.0);
        assertTrue(ia.lastPlacement().valid);
        w.place(b, "a", 0.0);
        assertFalse(ib.lastPlacement().valid);
        w.place(b, "b", 0.0);
        assertTrue(ib.lastPlacement().valid, "robots far apart do not block each other");
    }
}
