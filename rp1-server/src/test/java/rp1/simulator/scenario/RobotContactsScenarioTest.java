package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBody;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Contact sensors against other robots: a robot driven into another stops just short of it, and the
 * contact sensors that touch the other robot go hot with its name, on both robots, when the motion
 * ends; the moving robot's are released when it moves again, as against a wall. Robots with a
 * front "bumper" and a rear "tail" (each reaching 1 cm beyond the 15 cm chassis) in a 10 m hall.
 */
@Timeout(60)
class RobotContactsScenarioTest {
    private static final String PLAN = Plans.HALL
            + "placement above { geometry: 5, 3, -90, 0.1; }\n"
            + "placement eastFacingWest { geometry: 7, 2, 180, 0.1; }\n";

    private static List<String> contacts(ScenarioClient c, RsBody body) {
        List<String> out = new ArrayList<>();
        for (RsContactSensorEvent e : c.events(RsContactSensorEvent.class)) {
            out.add(body.getPartByID(e.sensorID).getName() + " " + e.status + " " + e.getNameOfObjectDetected()
                    + " @" + e.simTime);
        }
        return out;
    }

    private static double stopTime(double contact) {
        return Math.floor(1000.0 * contact - 0.1) / 1000.0;
    }

    @Test
    void headOnBumperToBumperBothBumpersGoHotWithTheOtherRobotsName() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsBody parkedBody = Bodies.withBumperAndTail("parked");
            ScenarioClient parked = s.connect(new ScenarioClient(parkedBody));
            parked.sendPlacementRequest("eastFacingWest");
            parked.await(RsPlacementEvent.class);
            RsBody moverBody = Bodies.withBumperAndTail("mover");
            ScenarioClient mover = s.connect(new ScenarioClient(moverBody));
            mover.once(RsPlacementEvent.class, e -> mover.sendMotionRequest(new RsMotionRequest(2.0, 0.0, 5.0)));
            mover.sendPlacementRequest("west");
            RsMotionHaltedEvent h = mover.await(RsMotionHaltedEvent.class);
            // Bumper fronts at x = 1.16 and 6.84: 5.68 m apart, closed at 2 m/s.
            double stop = stopTime(5.68 / 2.0);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, h.causeOfHalt);
            assertEquals(stop, h.simTime, 1e-9);
            assertEquals(List.of("bumper true parked @" + stop), contacts(mover, moverBody), "the tail sends nothing");
            parked.await(RsContactSensorEvent.class);
            assertEquals(List.of("bumper true mover @" + stop), contacts(parked, parkedBody));

            mover.sendMotionRequest(new RsMotionRequest(-0.5, 0.0, 1.0));
            mover.await(RsContactSensorEvent.class, e -> !e.status);
            assertEquals("bumper false  @" + stop, contacts(mover, moverBody).get(1), "released when it backs away");
        }
    }

    @Test
    void bumperIntoTheOthersSideOnlyTheMoversBumperGoesHot() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsBody parkedBody = Bodies.withBumperAndTail("parked");
            ScenarioClient parked = s.connect(new ScenarioClient(parkedBody));
            parked.sendPlacementRequest("centre");
            parked.await(RsPlacementEvent.class);
            RsBody moverBody = Bodies.withBumperAndTail("mover");
            ScenarioClient mover = s.connect(new ScenarioClient(moverBody));
            mover.once(RsPlacementEvent.class, e -> mover.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 2.0)));
            mover.sendPlacementRequest("above");
            RsMotionHaltedEvent h = mover.await(RsMotionHaltedEvent.class);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, h.causeOfHalt);
            assertEquals(List.of("bumper true parked @" + h.simTime), contacts(mover, moverBody));
            assertTrue(contacts(parked, parkedBody).isEmpty(), "its side is no contact sensor");
        }
    }

    @Test
    void aRobotBackingIntoAnotherPressesItsTailAndTheOthersBumper() throws Exception {
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RsBody parkedBody = Bodies.withBumperAndTail("parked");
            ScenarioClient parked = s.connect(new ScenarioClient(parkedBody));
            parked.sendPlacementRequest("west");
            parked.await(RsPlacementEvent.class);
            RsBody moverBody = Bodies.withBumperAndTail("mover");
            ScenarioClient mover = s.connect(new ScenarioClient(moverBody));
            mover.once(RsPlacementEvent.class, e -> mover.sendMotionRequest(new RsMotionRequest(-1.0, 0.0, 5.0)));
            mover.sendPlacementRequest("centre");
            RsMotionHaltedEvent h = mover.await(RsMotionHaltedEvent.class);
            // The mover's tail at x = 4.84 backs towards the parked bumper's front at 1.16: 3.68 m.
            double stop = stopTime(3.68);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, h.causeOfHalt);
            assertEquals(stop, h.simTime, 1e-9);
            assertEquals(List.of("tail true parked @" + stop), contacts(mover, moverBody));
            parked.await(RsContactSensorEvent.class);
            assertEquals(List.of("bumper true mover @" + stop), contacts(parked, parkedBody));
        }
    }

    /** A robot with a bumper and a tail parked at "centre", run into from the east and from {@code westPlacement}. */
    private record RunInto(ScenarioClient parked, RsBody parkedBody, RsMotionHaltedEvent fromEast,
                           RsMotionHaltedEvent fromWest) {
        static RunInto byTwo(Scenario s, String westPlacement) throws Exception {
            RsBody parkedBody = Bodies.withBumperAndTail("parked");
            ScenarioClient parked = s.connect(new ScenarioClient(parkedBody));
            ScenarioClient east = s.connect(new ScenarioClient(Bodies.round("fromEast")));
            ScenarioClient west = s.connect(new ScenarioClient(Bodies.round("fromWest")));
            east.once(RsPlacementEvent.class, e -> east.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 5.0)));
            west.once(RsPlacementEvent.class, e -> west.sendMotionRequest(new RsMotionRequest(1.0, 0.0, 5.0)));
            parked.sendPlacementRequest("centre");
            east.sendPlacementRequest("east");
            west.sendPlacementRequest(westPlacement);
            RunInto r = new RunInto(parked, parkedBody, east.await(RsMotionHaltedEvent.class),
                    west.await(RsMotionHaltedEvent.class));
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, r.fromEast.causeOfHalt);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, r.fromWest.causeOfHalt);
            return r;
        }
    }

    @Test
    void aParkedRobotRunIntoByTwoRobotsHasTheSensorsEachTouchedPressedWithItsName() throws Exception {
        // The parked robot's bumper (front at x = 5.16) is 3.69 m from the front of a robot coming
        // from the east, its tail (back at 4.84) 3.70 m from one coming from the west: both contacts
        // are found at the evaluation at 3.65 s, before the first of the two stops.
        String plan = PLAN + "placement farWest { geometry: 0.99, 2, 0, 0.1; }\n";
        try (Scenario s = Scenario.lockstep(plan)) {
            RunInto r = RunInto.byTwo(s, "farWest");
            assertEquals(stopTime(3.69), r.fromEast().simTime, 1e-9);
            assertEquals(stopTime(3.70), r.fromWest().simTime, 1e-9);
            r.parked().await(RsContactSensorEvent.class, e -> e.simTime >= r.fromWest().simTime);
            assertEquals(List.of("bumper true fromEast @" + r.fromEast().simTime,
                    "tail true fromWest @" + r.fromWest().simTime),
                    contacts(r.parked(), r.parkedBody()), "each pressed when the robot touching it stops");
        }
    }

    @Test
    void aParkedRobotRunIntoByTwoRobotsStoppingTogetherHasBothSensorsPressed() throws Exception {
        // Bumper and tail each 3.69 m from the robot coming at them: both robots stop at 3.689 s.
        try (Scenario s = Scenario.lockstep(PLAN)) {
            RunInto r = RunInto.byTwo(s, "west");
            double stop = stopTime(3.69);
            assertEquals(stop, r.fromEast().simTime, 1e-9);
            assertEquals(stop, r.fromWest().simTime, 1e-9);
            RsBody body = r.parkedBody();
            r.parked().await(RsContactSensorEvent.class, e -> body.getPartByID(e.sensorID).getName().equals("tail"));
            r.parked().await(RsContactSensorEvent.class, e -> body.getPartByID(e.sensorID).getName().equals("bumper"));
            assertEquals(List.of("bumper true fromEast @" + stop, "tail true fromWest @" + stop),
                    contacts(r.parked(), body), "in part order");
        }
    }
}
