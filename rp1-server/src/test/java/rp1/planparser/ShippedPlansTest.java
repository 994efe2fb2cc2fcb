package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsPolygon;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsSegment;
import rp1.rossum.RsTarget;
import rp1.rossum.RsWall;

/** The plans in FloorPlans/ parse, and their objects are where someone looking at the drawing expects. */
class ShippedPlansTest {
    private static final double IN = 39.3696;

    /** Distance in metres from (x, y) to the nearest wall or obstacle outline; negative inside one. */
    static double clearance(RsPlan plan, double x, double y) {
        double best = Double.POSITIVE_INFINITY;
        for (RsWall w : plan.getWallArray()) {
            double d = distanceToOutline(w.getPolygon(), x, y);
            best = Math.min(best, w.getPolygon().checkContainment(x, y) == RsPolygon.OUTSIDE ? d : -d);
        }
        return best;
    }

    static double distanceToOutline(RsPolygon polygon, double x, double y) {
        double best = Double.POSITIVE_INFINITY;
        for (RsSegment s : polygon.segment) {
            double len2 = s.v.x * s.v.x + s.v.y * s.v.y;
            double t = Math.max(0, Math.min(1, ((x - s.x) * s.v.x + (y - s.y) * s.v.y) / len2));
            best = Math.min(best, Math.hypot(x - s.x - t * s.v.x, y - s.y - t * s.v.y));
        }
        return best;
    }

    @Test
    void whiteRoomIsAThreeMetreRoomWithTheGoalAndHome() {
        RsPlan ours = TestPlans.parse(TestPlans.shipped("WhiteRoom.txt"));
        assertEquals("meters", ours.getUnits().getName());
        assertEquals(List.of("a", "b", "c", "d", "e", "goal", "home"),
                ours.getObjects().stream().map(RsObject::getName).collect(Collectors.toList()));
        assertEquals(3, ((RsTarget) ours.getObjectByName("goal")).lineWidth);
        assertEquals(3, ((RsPlacement) ours.getObjectByName("home")).lineWidth);
        RsRectangle b = ours.getBounds();
        assertArrayEquals(new double[] {-0.025, -0.025, 3.05, 3.05}, new double[] {b.x, b.y, b.width, b.height}, 1e-12);
    }

    @Test
    void whiteRoomIsTheWorldOfTheOriginalSample() {
        RsPlan original = TestPlans.parse(TestPlans.original("WhiteRoom.txt"));
        RsPlan ours = TestPlans.parse(TestPlans.shipped("WhiteRoom.txt"));
        assertEquals(original.getCaption(), ours.getCaption());
        assertEquals(original.getUnits().getName(), ours.getUnits().getName());
        assertEquals(original.getObjectCount(), ours.getObjectCount());
        for (int i = 0; i < original.getObjectCount(); i++) {
            RsObject o = original.getObjects().get(i);
            RsObject s = ours.getObjects().get(i);
            assertSame(o.getClass(), s.getClass());
            assertEquals(o.getName(), s.getName());
            assertArrayEquals(o.getGeometry(), s.getGeometry(), 1e-12, o.getName());
            assertEquals(o.label, s.label, o.getName());
            assertEquals(o.fillColor, s.fillColor, o.getName());
            assertEquals(o.lineColor, s.lineColor, o.getName());
        }
    }

    /** The contest arena's rooms in inches: x0, y0, x1, y1 (wall centre lines). */
    private static final double[][] ROOMS = {{0, 0, 36, 34}, {54, 0, 98, 34}, {54, 52, 98, 98}, {0, 52, 36, 98}};

    private static int roomOf(double x, double y) {
        for (int i = 0; i < ROOMS.length; i++) {
            double[] r = ROOMS[i];
            if (x * IN > r[0] && x * IN < r[2] && y * IN > r[1] && y * IN < r[3]) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void contestArenaIsAn98InchSquareInInches() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("contest.txt"));
        assertEquals("inches", plan.getUnits().getName());
        assertNotNull(plan.getCaption());
        RsRectangle b = plan.getBounds();
        assertArrayEquals(new double[] {-0.375 / IN, -0.375 / IN, 98.75 / IN, 98.75 / IN},
                new double[] {b.x, b.y, b.width, b.height}, 1e-9);
        assertEquals(12, plan.getWallArray().length);
    }

    @Test
    void contestHasOneCandleInEachRoomClearOfTheWalls() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("contest.txt"));
        RsTarget[] candles = plan.getTargetArray();
        assertEquals(4, candles.length);
        Set<Integer> rooms = new HashSet<>();
        for (RsTarget c : candles) {
            int room = roomOf(c.x, c.y);
            assertTrue(room >= 0, c.getName() + " is in a room");
            rooms.add(room);
            assertTrue(clearance(plan, c.x, c.y) > c.radius, c.getName() + " ring clear of walls");
            assertEquals(Color.red, c.lineColor);
        }
        assertEquals(4, rooms.size(), "one candle per room");
    }

    @Test
    void contestHomeIsInTheHallClearOfTheWalls() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("contest.txt"));
        RsPlacement home = (RsPlacement) plan.getObjectByName("home");
        assertTrue(home.x > 0 && home.x < 98 / IN && home.y > 0 && home.y < 98 / IN, "inside the arena");
        assertEquals(-1, roomOf(home.x, home.y), "in the hall, not in a room");
        assertTrue(clearance(plan, home.x, home.y) > home.radius, "home plate does not overlap a wall");
    }

    @Test
    void contestNavigationNetworkReachesEveryRoomAndHomeWithoutTouchingAWall() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("contest.txt"));
        RsNavNode[] nodes = plan.getNavNodeArray();
        for (RsNavNode n : nodes) {
            assertTrue(n.x > 0 && n.x < 98 / IN && n.y > 0 && n.y < 98 / IN, n.getName() + " inside the arena");
            assertTrue(clearance(plan, n.x, n.y) >= 5 / IN, n.getName() + " at least 5 in from any wall");
        }
        for (RsNavLink l : plan.getNavLinkArray()) {
            assertSame(l.n0, plan.getObjectByName(l.n0.getName()), l.getName());
            assertSame(l.n1, plan.getObjectByName(l.n1.getName()), l.getName());
            assertNotEquals(l.n0, l.n1, l.getName());
            for (double t = 0; t <= 1; t += 0.01) {
                double x = l.n0.x + t * (l.n1.x - l.n0.x);
                double y = l.n0.y + t * (l.n1.y - l.n0.y);
                assertTrue(clearance(plan, x, y) >= 5 / IN, l.getName() + " keeps 5 in from the walls");
            }
        }
        Set<RsNavNode> reached = reachable(nodes[0]);
        assertEquals(Set.of(nodes), reached, "the network is connected");
        RsPlacement home = (RsPlacement) plan.getObjectByName("home");
        assertTrue(reached.stream().anyMatch(n -> n.x == home.x && n.y == home.y), "a node at home");
        for (int room = 0; room < ROOMS.length; room++) {
            int r = room;
            assertTrue(reached.stream().anyMatch(n -> roomOf(n.x, n.y) == r), "a node in room " + (r + 1));
        }
    }

    private static Set<RsNavNode> reachable(RsNavNode start) {
        Set<RsNavNode> seen = new HashSet<>();
        Deque<RsNavNode> todo = new ArrayDeque<>();
        todo.add(start);
        while (!todo.isEmpty()) {
            RsNavNode n = todo.remove();
            if (seen.add(n)) {
                for (RsNavLink l : n.link) {
                    todo.add(l.getOtherNode(n));
                }
            }
        }
        return seen;
    }

    @Test
    void lineTrackIsABandAbout2CmWideWithTheStartOnIt() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("linetrack.txt"));
        RsPaint[] paint = plan.getPaintArray();
        assertEquals(2, paint.length);
        RsPaint outer = paint[0];
        RsPaint inner = paint[1];
        assertEquals(1, outer.getRegion());
        assertEquals(Color.black, outer.fillColor);
        assertEquals(2, inner.getRegion(), "the infield, declared later, lies on top");
        assertEquals(Color.white, inner.fillColor);
        for (RsSegment s : inner.getSegmentArray()) {
            assertEquals(RsPolygon.INSIDE, outer.getPolygon().checkContainment(s.x, s.y));
            double width = distanceToOutline(outer.getPolygon(), s.x, s.y);
            assertTrue(width > 0.019 && width < 0.021, "band width " + width);
        }
        RsPlacement start = plan.getPlacementArray()[0];
        assertEquals(RsPolygon.INSIDE, outer.getPolygon().checkContainment(start.x, start.y), "on the line");
        assertEquals(RsPolygon.OUTSIDE, inner.getPolygon().checkContainment(start.x, start.y), "not on the infield");
        assertEquals(0.0, start.orientation, "facing along the bottom straight");
        RsRectangle room = plan.getWallArray()[0].getBounds();
        room.union(plan.getWallArray()[2].getBounds());
        RsRectangle track = outer.getBounds();
        assertTrue(room.contains(track.x, track.y) && room.contains(track.x + track.width, track.y + track.height));
    }

    @Test
    void ackermanFieldLeavesRoomToTurnAroundHome() {
        RsPlan plan = TestPlans.parse(TestPlans.shipped("ackerman.txt"));
        RsPlacement home = (RsPlacement) plan.getObjectByName("home");
        RsRectangle field = plan.getBounds();
        assertTrue(field.width >= 8 && field.height >= 6, "a large room");
        assertTrue(field.contains(home.x, home.y));
        assertTrue(clearance(plan, home.x, home.y) >= 1.5, "1.5 m free around home");
        RsWall[] walls = plan.getWallArray();
        assertTrue(walls.length > 4, "some cones");
        for (int i = 4; i < walls.length; i++) {
            RsRectangle cone = walls[i].getBounds();
            assertTrue(field.contains(cone.x, cone.y) && field.contains(cone.x + cone.width, cone.y + cone.height));
            assertTrue(cone.width < 0.5, walls[i].getName() + " is a small cone");
        }
    }
}
