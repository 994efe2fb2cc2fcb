package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWheel;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;
import rp1.simulator.snapshot.PartSnapshot;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The picture of the WhiteRoom after ClientZero, painting, drove half a metre from "home" towards
 * the target (behavior.md sections 9 and 10), checked pixel by pixel.
 */
@Timeout(60)
class RendererTest {
    private static final int SIZE = 800;
    private static final Color WHITE = Color.white;

    private static WorldSnapshot drove;
    private static RsPlan plan;

    @BeforeAll
    static void driveHalfAMetreWhilePainting() throws Exception {
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            RsBody body = ClientZero.withPainter();
            ScenarioClient c = s.connect(new ScenarioClient(body));
            c.once(RsPlacementEvent.class, e -> {
                c.sendPainterActivationRequest(ClientZero.painterOf(body));
                c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 1.0));
            });
            c.sendPlacementRequest("home");
            c.await(RsMotionHaltedEvent.class);
            drove = Worlds.capture(s.simulation());
            plan = s.simulation().getWorld().getPlan();
        }
    }

    private static PixelProbe probe(WorldSnapshot snapshot) {
        Renderer r = new Renderer(snapshot.plan());
        BufferedImage image = Pictures.render(r, snapshot, SIZE, SIZE);
        return new PixelProbe(image, ViewTransform.fit(snapshot.plan().getBounds(), SIZE, SIZE));
    }

    private static RsPlacement home() {
        return plan.getPlacementArray()[0];
    }

    /** Where the robot ended: 0.5 m from home along its heading of 225 degrees. */
    private static RsTransform endPose() {
        RsPlacement h = home();
        return new RsTransform(h.orientation, h.x + 0.5 * Math.cos(h.orientation), h.y + 0.5 * Math.sin(h.orientation));
    }

    @Test
    void theSnapshotHasTheRobotWhereTheMotionEnded() {
        RobotSnapshot r = drove.placedRobots().get(0);
        RsTransform end = endPose();
        assertEquals(end.m13, r.x(), 1e-9);
        assertEquals(end.m23, r.y(), 1e-9);
        assertEquals(1.0, drove.simTime(), 1e-9);
    }

    @Test
    void wallsAreFilledInTheirFillColour() {
        PixelProbe p = probe(drove);
        assertEquals(Color.lightGray, p.at(1.5, 0.0), "south wall, centre line");
        assertEquals(Color.lightGray, p.at(1.5, 1.5), "diagonal wall e, centre line");
        assertEquals(WHITE, p.at(1.5, 0.5), "the floor");
    }

    @Test
    void theTargetIsARingOfItsLineWidthWithWhiteInside() {
        PixelProbe p = probe(drove);
        double scale = ViewTransform.fit(plan.getBounds(), SIZE, SIZE).getScale();
        assertTrue(p.near(0.4 + 0.25 - 1.5 / scale, 0.4, 1, Color.red), "ring on the east side of the goal");
        assertTrue(p.near(0.4, 0.4 - 0.25 + 1.5 / scale, 1, Color.red), "ring on the south side of the goal");
        assertEquals(WHITE, p.at(0.4, 0.4 + 0.15), "inside the ring, above the label");
    }

    @Test
    void theLabelOfTheTargetIsDrawnInItsFillColourOnTheTarget() {
        PixelProbe p = probe(drove);
        assertTrue(p.near(0.4, 0.4, 6, Color.red), "\"Goal\" centred on the target");
    }

    @Test
    void thePlacementIsAGreenHomePlatePointingAlongItsOrientation() {
        PixelProbe p = probe(drove);
        RsPlacement h = home();
        double scale = ViewTransform.fit(plan.getBounds(), SIZE, SIZE).getScale();
        double s = h.radius * scale;
        RsTransform local = new RsTransform(h.orientation, h.x, h.y);
        double back = -0.8485 * (s - 1.5) / scale;
        double side = 0.8485 * (s - 1.5) / scale;
        double[][] ring = {{back, 0.0}, {-0.2 * h.radius, side}, {-0.2 * h.radius, -side}};
        for (double[] b : ring) {
            var w = local.map(b[0], b[1]);
            assertTrue(p.near(w.x, w.y, 1, Color.green), "plate ring at local " + b[0] + ", " + b[1]);
        }
        var behind = local.map(-1.2 * h.radius, 0.0);
        assertEquals(WHITE, p.at(behind.x, behind.y), "nothing beyond the back of the plate");
    }

    @Test
    void theRobotIsDrawnAtItsPoseInItsPartsColours() {
        PixelProbe p = probe(drove);
        RsTransform end = endPose();
        assertEquals(Color.lightGray, p.atBody(end, -0.11, 0.0), "chassis");
        assertEquals(Color.blue, p.atBody(end, ClientZero.HEAD_X, 0.0), "head (cold: nothing in sight)");
        assertEquals(Color.darkGray, p.atBody(end, 0.05, ClientZero.TRACK_WIDTH / 2), "left wheel");
        assertEquals(Color.darkGray, p.atBody(end, -0.05, -ClientZero.TRACK_WIDTH / 2), "right wheel");
        assertEquals(WHITE, p.atBody(end, 0.0, ClientZero.RADIUS + 0.03), "the floor beside it");
    }

    @Test
    void thePaintTrailRunsFromHomeToTheRobotUnderneathIt() {
        PixelProbe p = probe(drove);
        RsPlacement h = home();
        double c = Math.cos(h.orientation);
        double s = Math.sin(h.orientation);
        assertEquals(ClientZero.TRAIL, p.at(h.x + 0.3 * c, h.y + 0.3 * s), "0.3 m along the path");
        assertEquals(ClientZero.TRAIL, p.at(h.x + 0.1 * c, h.y + 0.1 * s), "over the home plate");
        double px = ClientZero.TRAIL_WIDTH * 0.3;
        assertEquals(ClientZero.TRAIL, p.at(h.x + 0.3 * c - px * s, h.y + 0.3 * s + px * c), "within its width");
        assertEquals(Color.blue, p.atBody(endPose(), ClientZero.HEAD_X, 0.0), "robots are drawn over trails");
        assertEquals(Color.lightGray, p.atBody(endPose(), -0.05, 0.0), "the robot hides the trail under it");
    }

    @Test
    void partsAreDrawnHotFromTheSnapshotNotFromTheirLiveState() {
        RobotSnapshot r = drove.placedRobots().get(0);
        List<PartSnapshot> parts = new ArrayList<>();
        for (PartSnapshot part : r.parts()) {
            boolean head = "head".equals(part.part().getName());
            parts.add(new PartSnapshot(part.part(), head, part.steering()));
        }
        PixelProbe p = probe(withRobot(new RobotSnapshot(r.number(), r.label(), true, r.x(), r.y(), r.theta(), parts)));
        assertEquals(new Color(255, 200, 0), p.atBody(endPose(), ClientZero.HEAD_X, 0.0), "the default hot fill, orange");
        assertEquals(Color.blue, probe(drove).atBody(endPose(), ClientZero.HEAD_X, 0.0), "the live part is cold");
    }

    @Test
    void wheelsAreTurnedByTheirSteeringAngleAboutTheirHubs() {
        RobotSnapshot r = drove.placedRobots().get(0);
        List<PartSnapshot> parts = new ArrayList<>();
        for (PartSnapshot part : r.parts()) {
            boolean left = part.part() instanceof RsWheel w && w.getY() > 0.0;
            parts.add(new PartSnapshot(part.part(), part.hot(), left ? Math.PI / 2 : part.steering()));
        }
        PixelProbe p = probe(withRobot(new RobotSnapshot(r.number(), r.label(), true, r.x(), r.y(), r.theta(), parts)));
        double hub = ClientZero.TRACK_WIDTH / 2;
        assertEquals(Color.darkGray, p.atBody(endPose(), 0.0, hub - 0.06), "the turned wheel reaches across");
        assertEquals(Color.lightGray, p.atBody(endPose(), 0.06, hub), "and no longer lies along the body");
    }

    @Test
    void aRobotWhoseWheelsSlipIsDrawnOverAGreyOutlineWhereItBelievesItIs() {
        RobotSnapshot r = drove.placedRobots().get(0);
        RsPlacement h = home();
        RobotSnapshot slipped = new RobotSnapshot(r.number(), r.label(), true, r.x(), r.y(), r.theta(), r.parts(),
                new double[] {h.x, h.y, h.orientation});
        var side = new RsTransform(h.orientation, h.x, h.y).map(0.0, ClientZero.RADIUS);
        Color grey = new Color(150, 150, 150);
        assertTrue(probe(withRobot(slipped)).near(side.x, side.y, 1, grey), "the believed chassis's edge at home");
        assertTrue(!probe(drove).near(side.x, side.y, 1, grey), "nothing there for a robot that does not slip");
        assertEquals(Color.lightGray, probe(withRobot(slipped)).atBody(endPose(), -0.11, 0.0), "the true robot as ever");
    }

    @Test
    void unplacedRobotsAreNotDrawn() {
        RobotSnapshot r = drove.placedRobots().get(0);
        PixelProbe p = probe(withRobot(new RobotSnapshot(r.number(), r.label(), false, r.x(), r.y(), r.theta(), r.parts())));
        assertEquals(WHITE, p.atBody(endPose(), ClientZero.HEAD_X, 0.0));
    }

    @Test
    void deselectedTargetsAreNotDrawn() {
        WorldSnapshot deselected = new WorldSnapshot(drove.plan(), drove.simTime(), List.of(false), drove.robots(),
                drove.trails());
        PixelProbe p = probe(deselected);
        double scale = ViewTransform.fit(plan.getBounds(), SIZE, SIZE).getScale();
        assertEquals(WHITE, p.at(0.4 + 0.25 - 1.5 / scale, 0.4));
        assertEquals(WHITE, p.at(0.4, 0.4));
    }

    private static WorldSnapshot withRobot(RobotSnapshot r) {
        return new WorldSnapshot(drove.plan(), drove.simTime(), drove.targetSelected(), List.of(r), drove.trails());
    }
}
