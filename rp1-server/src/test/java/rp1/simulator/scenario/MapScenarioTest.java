package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Set;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.planparser.StageMaps;
import rp1.rossum.RsPlan;
import rp1.rossum.RsSegment;
import rp1.rossum.RsWall;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * A robot in a plan whose walls come from a map image (FloorPlans/rooms.yaml: 5 cm pixels, a wall
 * x = 3.0 to 3.1 m with a doorway, a pixelated pillar of radius 0.3 m at (1.5, 2.6)) drives in the free
 * space and stops where the image is black, and the client receives the map's walls with the plan.
 */
class MapScenarioTest {
    private static final Path ROOMS = Paths.get(System.getProperty("rp1.root", ".")).resolve("FloorPlans/rooms.yaml")
            .toAbsolutePath();
    private static final String PLAN = "bitmap rooms { map: \"" + ROOMS.toString().replace("\\", "\\\\") + "\"; }\n"
            + "placement diagonal { geometry: 0.7, 0.7, 45, 0.1; }\n"
            + "placement belowPillar { geometry: 1.5, 1.0, 90, 0.1; }\n";

    private static RsMotionHaltedEvent drive(Scenario s, String placement, double distance) throws InterruptedException {
        ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
        c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, distance / 0.5)));
        c.sendPlacementRequest(placement);
        return c.await(RsMotionHaltedEvent.class);
    }

    @Test
    void aRobotDrivesThroughFreeSpaceToTheEndOfItsMotion() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsMotionHaltedEvent halted = drive(s, "diagonal", 1.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COMPLETION, halted.causeOfHalt);
            assertEquals(0.7 + Math.sqrt(0.5), halted.x, 1e-9);
            assertEquals(0.7 + Math.sqrt(0.5), halted.y, 1e-9);
        }
    }

    @Test
    void aRobotStopsAtTheFaceOfTheBlackPixelsOfTheDividingWall() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsMotionHaltedEvent halted = drive(s, "diagonal", 10.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt);
            assertEquals(3.0 - Bodies.RADIUS, halted.x, 0.001, "touching x = 3.0, the wall's west face");
            assertEquals(halted.x, halted.y, 1e-9, "on the diagonal, at y = " + halted.y + ", where the wall is black");
            try (Scenario declared = Scenario.lockstep("wall w { geometry: 3.05, 2.4, 3.05, 3.9, 0.1; }\n" + PLAN
                    .substring(PLAN.indexOf('\n') + 1))) {
                RsMotionHaltedEvent same = drive(declared, "diagonal", 10.0);
                assertEquals(same.simTime, halted.simTime, "where a wall declared in plan text stops it (the round"
                        + " chassis meets a face at 45 degrees within a millimetre)");
                assertEquals(same.x, halted.x, 1e-12);
            }
        }
    }

    @Test
    void aRobotStopsAtTheLowestRowOfThePixelatedPillar() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsMotionHaltedEvent halted = drive(s, "belowPillar", 10.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt);
            double face = 2.3 - Bodies.RADIUS;
            assertTrue(halted.y <= face && halted.y > face - 0.001, "touching y = 2.3, the pillar's lowest pixels: "
                    + halted.y);
            assertEquals(1.5, halted.x, 1e-9);
        }
    }

    @Test
    void theClientReceivesTheMapsWallsAsWalls() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsPlan parsed = Scenario.plan(PLAN);
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlanRequest();
            RsPlan received = (RsPlan) c.await(RsPlanEvent.class).plan;
            RsWall[] walls = received.getWallArray();
            assertEquals(parsed.getWallArray().length, walls.length);
            assertTrue(walls.length > 4);
            for (int i = 0; i < walls.length; i++) {
                assertEquals("rooms_" + (i + 1), walls[i].getName());
                assertArrayEquals(parsed.getWallArray()[i].getGeometry(), walls[i].getGeometry(), 1e-12);
            }
        }
    }

    @Test
    void inStagesCaveARobotDrivesFromFreeSpaceUntilItTouchesTheRock(@TempDir Path dir) throws Exception {
        StageMaps.extract(dir, Set.of("cave.png"));
        BufferedImage image = ImageIO.read(dir.resolve("cave.png").toFile());
        double resolution = 16.0 / image.getWidth();
        double[] start = freeSpot(image.getRaster(), resolution, 0.5);
        String plan = "bitmap cave { image: \"" + dir.resolve("cave.png").toString().replace("\\", "\\\\")
                + "\"; resolution: " + resolution + "; }\nplacement start { geometry: " + start[0] + ", " + start[1]
                + ", 0, 0.1; }\n";
        try (Scenario s = Scenario.lockstep(plan)) {
            RsMotionHaltedEvent halted = drive(s, "start", 40.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, halted.causeOfHalt, "the cave is closed to the east");
            assertTrue(halted.x > start[0] + 0.3, "it drove: from " + start[0] + " to " + halted.x);
            assertEquals(start[1], halted.y, 1e-9);
            double clearance = clearance(Scenario.plan(plan), halted.x, halted.y);
            assertEquals(Bodies.RADIUS, clearance, 0.0015, "touching a wall of black pixels, not inside one");
        }
    }

    /** The first point (on a 10-pixel lattice) with no black pixel within {@code radius} metres. */
    private static double[] freeSpot(Raster r, double resolution, double radius) {
        int reach = (int) Math.ceil(radius / resolution);
        for (int row = reach; row < r.getHeight() - reach; row += 10) {
            for (int col = reach; col < r.getWidth() - reach; col += 10) {
                if (clear(r, col, row, reach)) {
                    return new double[] {(col + 0.5) * resolution, (r.getHeight() - row - 0.5) * resolution};
                }
            }
        }
        throw new AssertionError("no free spot in the map");
    }

    private static boolean clear(Raster r, int col, int row, int reach) {
        for (int dr = -reach; dr <= reach; dr++) {
            for (int dc = -reach; dc <= reach; dc++) {
                if (dr * dr + dc * dc <= reach * reach && r.getSample(col + dc, row + dr, 0) < 128) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Distance from (x, y) to the nearest wall outline. */
    private static double clearance(RsPlan plan, double x, double y) {
        double best = Double.POSITIVE_INFINITY;
        for (RsWall w : plan.getWallArray()) {
            for (RsSegment g : w.getSegmentArray()) {
                double len2 = g.v.x * g.v.x + g.v.y * g.v.y;
                double t = Math.max(0, Math.min(1, ((x - g.x) * g.v.x + (y - g.y) * g.v.y) / len2));
                best = Math.min(best, Math.hypot(x - g.x - t * g.v.x, y - g.y - t * g.v.y));
            }
        }
        return best;
    }
}
