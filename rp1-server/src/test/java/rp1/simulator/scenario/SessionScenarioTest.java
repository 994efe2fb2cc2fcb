package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.awt.Color;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsEncoder;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.world.PaintTrail;
import rp1.simulator.world.Robot;
import rp1.simulator.world.TrailSegment;

/** What a client session does with the less common requests: painters, encoders, selection, clicks, leaving. */
@Timeout(60)
class SessionScenarioTest {

    @Test
    void anActivePainterLeavesATrailPointAtEveryStep() throws Exception {
        RsBody body = Bodies.round("painter bot");
        RsBodyPainter pen = new RsBodyPainter(Bodies.box(-0.12, -0.08), 4);
        pen.setName("pen");
        pen.setTrailerPosition(-0.1, 0.0);
        pen.setTrailerWidth(0.02);
        pen.setPaintColor(Color.red);
        body.addPart(pen);
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(body));
            c.once(RsPlacementEvent.class, e -> {
                c.sendPainterActivationRequest(pen);
                c.sendMotionRequest(new RsMotionRequest(0.3, 0.0, 1.0));
            });
            c.sendPlacementRequest("west");
            c.await(RsMotionHaltedEvent.class);
            c.sendTimeoutRequest(0.0);
            c.await(RsTimeoutEvent.class);
            Robot robot = s.simulation().getWorld().getRobots().get(0);
            PaintTrail trail = robot.getTrails().get(0);
            List<TrailSegment> segments = trail.getSegments();
            assertEquals(1, segments.size());
            TrailSegment seg = segments.get(0);
            assertEquals(Color.red, seg.getColor());
            assertEquals(0.02, seg.getWidth());
            assertEquals(21, seg.getCount(), "a point at every 1.5 cm step over 30 cm, both ends included");
            assertEquals(0.9, seg.getX(0), 1e-6, "the trailer point 10 cm behind the centre at the start");
            assertEquals(1.2, seg.getX(seg.getCount() - 1), 1e-6);
            assertTrue(robot.getBody().getPartByName("pen").getHot(), "an active painter is drawn hot");
        }
    }

    @Test
    void encoderStatusReportsTheWheelsTurnsAndClearsWhenAsked() throws Exception {
        RsBody body = new RsBody("encoded");
        RsDifferentialSteering drive = new RsDifferentialSteering(0.3, 0.05);
        drive.addDefaultWheels(0.05, 0.02);
        RsEncoder[] encoders = drive.addEncodersToDefaultWheels(100);
        body.addPart(new rp1.rossum.RsBodyCircle(0, 0, 0.2));
        body.addPart(drive);
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(body));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.1 * Math.PI, 0.0, 1.0)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.0, 0.0, 1.0)));
            c.on(RsMotionHaltedEvent.class, e -> {
                if (e.duration == 0.0) {
                    c.sendEncoderStatusRequest(encoders, true);
                }
            });
            c.sendPlacementRequest("west");
            c.await(RsEncoderStatusEvent.class, e -> e.encoderID == encoders[1].getID());
            List<RsEncoderStatusEvent> reports = c.events(RsEncoderStatusEvent.class);
            assertEquals(2, reports.size());
            RsEncoderStatusEvent left = reports.get(0);
            assertEquals(encoders[0].getID(), left.encoderID);
            // 0.1 pi m of travel on a 5 cm wheel is one full turn: 100 intervals, all but the first step's 10 counted.
            assertEquals(1, left.quadratureValue);
            assertTrue(left.accumulatorValue >= 90 && left.accumulatorValue <= 100, "accumulator " + left.accumulatorValue);
            assertTrue(left.clearOnReport);
        }
    }

    @Test
    void targetSelectionAnswersAtOnceForEachTargetTouched() throws Exception {
        String targets = "target t1 { geometry: 2, 1, 0.1; }\ntarget t2 { geometry: 3, 1, 0.1; }\n";
        try (Scenario s = Scenario.lockstep(Plans.HALL + targets)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendExclusiveTargetSelectionRequest("t2");
            c.await(RsTargetSelectionEvent.class, e -> e.targetName.equals("t2"));
            List<RsTargetSelectionEvent> events = c.events(RsTargetSelectionEvent.class);
            assertEquals(2, events.size(), "exclusive touches every target");
            assertEquals("t1", events.get(0).targetName);
            assertFalse(events.get(0).status);
            assertTrue(events.get(1).status);
            c.sendTargetSelectionRequest("nonexistent", true);
            c.sendTimeoutRequest(0.0);
            c.await(RsTimeoutEvent.class);
            assertEquals(2, c.events(RsTargetSelectionEvent.class).size(), "an unknown name touches nothing");
        }
    }

    @Test
    void mouseClicksReachEverySubscribedClientWithARobot() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.sendTimeoutRequest(1.0);
            c.await(RsTimeoutEvent.class);
            s.simulation().mouseClick(1, 2, 3.5, 1.25);
            RsMouseClickEvent click = c.await(RsMouseClickEvent.class);
            assertEquals(1, click.button);
            assertEquals(2, click.clickCount);
            assertEquals(3.5, click.x);
            assertEquals(1.25, click.y);
        }
    }

    @Test
    void requestsAboutTheRobotBeforeItsBodyAreIgnoredAndTheSessionGoesOn() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = new ScenarioClient(Bodies.round("late")) {
                @Override
                public void join() {
                    sendMotionRequest(new RsMotionRequest(1, 0, 1));
                    sendPositionRequest();
                    sendPlacementRequest("west");
                    sendTimeoutRequest(0.5);
                    addTimeoutEventHandler(e -> { });
                    super.join();
                }
            };
            s.connect(c);
            c.sendPositionRequest();
            RsPositionEvent p = c.await(RsPositionEvent.class);
            assertEquals(0.0, p.x, "never placed: the body arrived after the placement request");
            assertTrue(c.events(RsPlacementEvent.class).isEmpty());
        }
    }

    @Test
    void aClientThatLeavesTakesItsRobotOutOfTheWorld() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient stay = s.connect(new ScenarioClient(Bodies.round("stay")));
            stay.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            ScenarioClient leave = s.connect(new ScenarioClient(Bodies.round("leave")));
            leave.sendPlacementRequest("centre");
            leave.await(RsPlacementEvent.class);
            assertEquals(2, s.simulation().getWorld().getRobots().size());
            s.closeClient(1);
            await(() -> s.simulation().getSessions().size() == 1, Duration.ofSeconds(10), "the server noticed the client leave");
            stay.sendTimeoutRequest(1.0);
            stay.await(RsTimeoutEvent.class);
            assertEquals(1, s.simulation().getWorld().getRobots().size());
            stay.sendPlacementRequest("centre");
            assertTrue(stay.await(RsPlacementEvent.class).valid, "the place is free again");
        }
    }
}
