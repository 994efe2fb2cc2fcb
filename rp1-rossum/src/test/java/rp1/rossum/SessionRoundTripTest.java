package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsSensorRequest;

/**
 * A whole robot through a real client and server connection, in-process and over a loopback socket:
 * the body with every part type, sensor events reaching the handler registered for their sensor,
 * sensor polling and painter requests, and a plan with every object type.
 */
@Timeout(30)
class SessionRoundTripTest {
    private static final double[] BOX = {0.0, -0.05, 0.1, -0.05, 0.1, 0.05, 0.0, 0.05};

    /** A body with one part of every transmittable type. */
    static final class Robot {
        final RsBody body = new RsBody("everything");
        /** Wheels right after their wheel system, so the server infers the same wheel ids (section 8.6). */
        final RsDifferentialSteering drive = driveWithWheels();
        final RsEncoder[] encoders = drive.addEncodersToDefaultWheels(64);
        final RsBodyCircle chassis = new RsBodyCircle(0, 0, 0.2);
        final RsBodyShape hull = new RsBodyShape(new double[] {-0.2, -0.1, 0.2, -0.1, 0.2, 0.1}, 3);
        final RsBodyTargetSensor head = new RsBodyTargetSensor(BOX, 4, 0.1, 0.0, 0.0, Math.PI / 4, 2.0, 3, 4);
        final RsBodyContactSensor bumper = new RsBodyContactSensor(BOX, 4);
        final RsBodyRangeSensor sonar = new RsBodyRangeSensor(BOX, 4, 0.1, 0.0, 0.2, 3.0, 10);
        final RsBodyPaintSensor eye = new RsBodyPaintSensor(BOX, 4, 0.05, 0.0);
        final RsBodyPainter pen = new RsBodyPainter(BOX, 4);

        private static RsDifferentialSteering driveWithWheels() {
            RsDifferentialSteering d = new RsDifferentialSteering(0.3, 0.05);
            d.addDefaultWheels(0.05, 0.02);
            return d;
        }

        Robot() {
            chassis.setName("chassis");
            chassis.setFillColor(Color.yellow);
            head.setName("head");
            head.setHotFillColor(Color.red);
            bumper.setName("bumper");
            sonar.setName("sonar");
            eye.setName("eye");
            eye.setRegionSensitivity(new int[] {1, 3});
            pen.setName("pen");
            for (RsBodyPart p : new RsBodyPart[] {chassis, hull, head, bumper, sonar, eye, pen, drive}) {
                body.addPart(p);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void theBodyArrivesWithEveryPartTypeAndTheClientsIds(String transport) throws Exception {
        Robot robot = new Robot();
        try (Link link = RequestRoundTripTest.link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            link.client.sendBodySpecification(robot.body);
            RsBody got = (RsBody) server.received.next();
            assertEquals("everything", got.getName());
            RsBodyPart[] sent = robot.body.getBodyPartArray();
            RsBodyPart[] parts = got.getBodyPartArray();
            assertEquals(sent.length, parts.length);
            for (int i = 0; i < sent.length; i++) {
                assertSame(sent[i].getClass(), parts[i].getClass(), "part " + i);
                assertEquals(sent[i].getID(), parts[i].getID(), "id of part " + i);
                assertEquals(sent[i].getName(), parts[i].getName(), "name of part " + i);
            }
            assertEquals(Color.yellow, got.getPartByName("chassis").getFillColor());
            RsWheelSystem wheels = got.wheelSystem;
            assertEquals(2, wheels.getWheels().length);
            assertEquals(robot.encoders[0].getID(), wheels.getWheels()[0].getID(), "left encoder id agrees");
            assertEquals(robot.encoders[1].getID(), wheels.getWheels()[1].getID(), "right encoder id agrees");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void addingASensorHandlerSubscribesToThatSensorsEvents(String transport) throws Exception {
        Robot robot = new Robot();
        try (Link link = RequestRoundTripTest.link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            RsClient c = link.client;
            Capture<RsSensorEvent> events = new Capture<>();
            link.startServer();
            c.addTargetSensorEventHandler(robot.head, events::add);
            c.addContactSensorEventHandler(robot.bumper, events::add);
            c.addRangeSensorEventHandler(robot.sonar, events::add);
            c.addPaintSensorEventHandler(robot.eye, events::add);
            for (int i = 0; i < 4; i++) {
                server.received.next();
            }
            assertTrue(link.connection.isClientSubscribedToEvent(4, robot.head.getID()));
            assertTrue(link.connection.isClientSubscribedToEvent(11, robot.eye.getID()));
            assertTrue(link.connection.isClientSubscribedToEvent(0, robot.bumper.getID()));
            assertTrue(link.connection.isClientSubscribedToEvent(3, robot.sonar.getID()));
            assertFalse(link.connection.isClientSubscribedToEvent(3, robot.head.getID()));
        }
    }

    @Test
    void sensorsWithIdsAbove1000CanStillSubscribe() throws Exception {
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(BOX, 4, 0.1, 0.0, 0.0, 3.0, 10);
        sonar.assignID(5000);
        try (Link link = Link.piped(ClientEventLoopTest.quietClient(), new RsConnection())) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            link.client.addRangeSensorEventHandler(sonar, e -> { });
            server.received.next();
            assertTrue(link.connection.isClientSubscribedToEvent(3, 5000),
                    "RP1 0.60 ignored indices above 1000; many in-process robots pass that quickly");
        }
    }

    @Test
    void sensorEventsOfEveryKindArriveIntact() throws Exception {
        Robot robot = new Robot();
        try (Link link = Link.piped(ClientEventLoopTest.quietClient(), new RsConnection())) {
            Capture<RsSensorEvent> events = new Capture<>();
            RsClient c = link.client;
            c.addTargetSensorEventHandler(robot.head, events::add);
            c.addContactSensorEventHandler(robot.bumper, events::add);
            c.addRangeSensorEventHandler(robot.sonar, events::add);
            c.addPaintSensorEventHandler(robot.eye, events::add);
            link.startServer().startClientLoop();
            RsConnection s = link.connection;
            s.sendTargetSensorEvent(new RsTargetSensorEvent(1.0, robot.head.getID(), 1, 2, 0.6, 0.8, true, 1.5, 0.25, 1.52, 0.165, "F1"));
            s.sendContactSensorEvent(2.0, robot.bumper.getID(), true, "north wall");
            s.sendRangeSensorEvent(new RsRangeSensorEvent(3.0, robot.sonar.getID(), 1, 2, 0, 0, true, 0.75, "east wall"));
            s.sendPaintSensorEvent(new RsPaintSensorEvent(4.0, robot.eye.getID(), 1, 2, false, 2));
            s.sendTargetSensorEvent(new RsTargetSensorEvent(5.0, 999, 0, 0, 0, 0, false, 0, 0, 0, 0));
            s.sendPaintSensorEvent(new RsPaintSensorEvent(6.0, robot.eye.getID(), 1, 2, true, 3));

            RsTargetSensorEvent t = (RsTargetSensorEvent) events.next();
            assertEquals(robot.head.getID(), t.sensorID);
            assertEquals(0.8, t.uy);
            assertEquals(1.52, t.range);
            assertEquals(0.165, t.bearing);
            assertEquals("F1", t.getNameOfObjectDetected());
            RsContactSensorEvent contact = (RsContactSensorEvent) events.next();
            assertTrue(contact.status);
            assertEquals("north wall", contact.getNameOfObjectDetected());
            RsRangeSensorEvent range = (RsRangeSensorEvent) events.next();
            assertEquals(0.75, range.range);
            assertEquals("east wall", range.getNameOfObjectDetected());
            RsPaintSensorEvent paint = (RsPaintSensorEvent) events.next();
            assertFalse(paint.status);
            assertEquals(2, paint.region);
            RsPaintSensorEvent second = (RsPaintSensorEvent) events.next();
            assertEquals(6.0, second.simTime, "the event for unknown sensor 999 was dropped");
            assertEquals(3, second.region);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void anAckermanCarWithACasterArrivesWithItsDerivedSteeringLimit(String transport) throws Exception {
        RsBody car = new RsBody("car");
        RsAckermanSteering steering = new RsAckermanSteering(0.3, 0.4, 0.06, Math.toRadians(40), false);
        steering.addDefaultWheels(0.06, 0.03, 0.05, 0.01);
        steering.addDefaultCasterWheel(-0.2, 0.0, 0.03, 0.02);
        car.addPart(new RsBodyShape(new double[] {-0.25, -0.2, 0.55, -0.2, 0.55, 0.2, -0.25, 0.2}, 4));
        car.addPart(steering);
        try (Link link = RequestRoundTripTest.link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            link.client.sendBodySpecification(car);
            RsBody got = (RsBody) server.received.next();
            RsAckermanSteering s = (RsAckermanSteering) got.wheelSystem;
            assertEquals(steering.getID(), s.getID());
            assertEquals(steering.getWheels().length, s.getWheels().length);
            assertTrue(s.getWheels()[s.getWheels().length - 1] instanceof RsWheelCaster);
            assertEquals(0.4, s.getWheelBase());
            assertTrue(s.getMaxAbsSteeringAngle() < steering.getMaxAbsSteeringAngle(),
                    "the server re-derives the limit from the already derived value, as RP1 0.60 does");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void sensorPollingAndPainterRequestsArrive(String transport) throws Exception {
        Robot robot = new Robot();
        try (Link link = RequestRoundTripTest.link(transport)) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsClient c = link.client;
            c.sendSensorStatusRequest(robot.sonar);
            robot.pen.setTrailerPosition(-0.1, 0.0);
            robot.pen.setTrailerWidth(0.02);
            robot.pen.setPaintColor(new Color[] {Color.red, Color.blue});
            c.sendPainterActivationRequest(robot.pen);
            c.sendPainterDeactivationRequest(robot.pen);
            c.sendPainterErasureRequest(robot.pen);

            assertEquals(robot.sonar.getID(), ((RsSensorRequest) server.received.next()).sensorID);
            RsPainterChangeRequest on = (RsPainterChangeRequest) server.received.next();
            assertEquals(robot.pen.getID(), on.painterID);
            assertTrue(on.activation);
            assertTrue(on.trailerDefined);
            assertEquals(-0.1, on.xTrailer);
            assertEquals(0.02, on.wTrailer);
            assertArrayEquals(new Color[] {Color.red, Color.blue}, on.color);
            RsPainterChangeRequest off = (RsPainterChangeRequest) server.received.next();
            assertFalse(off.activation);
            assertFalse(off.erasure);
            assertTrue(((RsPainterChangeRequest) server.received.next()).erasure);
            assertFalse(robot.pen.getPainterActivationStatus());
        }
    }

    @Test
    void activatingAPainterWithoutATrailerSendsADeactivationInsteadOfHalfAMessage() throws Exception {
        try (Link link = Link.piped(ClientEventLoopTest.quietClient(), new RsConnection())) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            RsBodyPainter pen = new RsBodyPainter(BOX, 4);
            pen.setPaintColor(Color.green);
            link.client.sendPainterActivationRequest(pen);
            link.client.sendPositionRequest();
            RsPainterChangeRequest r = (RsPainterChangeRequest) server.received.next();
            assertFalse(r.activation);
            assertEquals("position", server.received.next(), "the stream is still in step");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"piped", "socket", "direct"})
    void aPlanWithEveryObjectTypeArrives(String transport) throws Exception {
        RsPlan plan = new RsPlan();
        plan.setCaption("Every object");
        RsWall wall = new RsWall("w", plan);
        wall.setGeometry(new double[] {0, 0, 3, 0, 0.05});
        plan.addObject(wall);
        RsWall obstacle = new RsWall("o", plan);
        obstacle.setGeometry(new double[] {1, 1, 2, 1, 1.5, 2});
        plan.addObject(obstacle);
        RsTarget target = new RsTarget("t", plan);
        target.setGeometry(new double[] {0.4, 0.4, 0.25});
        plan.addObject(target);
        RsPlacement home = new RsPlacement("home", plan);
        home.setGeometry(new double[] {2.5, 2.5, 225 * Math.PI / 180, 0.275});
        plan.addObject(home);
        RsNavNode a = new RsNavNode("a", plan);
        a.setGeometry(new double[] {0.5, 0.5});
        a.setLabel("A");
        a.setColor(Color.magenta);
        plan.addObject(a);
        RsNavNode b = new RsNavNode("b", plan);
        b.setGeometry(new double[] {2.5, 0.5});
        plan.addObject(b);
        RsNavLink ab = new RsNavLink("ab", plan);
        ab.setNodes(a, b);
        ab.setLabel("road");
        plan.addObject(ab);
        RsPaint paint = new RsPaint("p", plan);
        paint.setGeometry(new double[] {0, 2, 1, 2, 1, 3});
        paint.setFillColor(Color.black);
        plan.addObject(paint);

        try (Link link = RequestRoundTripTest.link(transport)) {
            Capture<RsPlanEvent> events = new Capture<>();
            link.client.addPlanEventHandler(events::add);
            link.startServer().startClientLoop();
            link.connection.sendPlanEvent(new RsPlanEvent(0.0, plan));
            RsPlan got = (RsPlan) events.next().plan;
            assertEquals("Every object", got.getCaption());
            RsObject[] objects = got.getObjectArray();
            assertEquals(8, objects.length);
            assertArrayEquals(wall.getGeometry(), objects[0].getGeometry());
            assertTrue(objects[1] instanceof RsWall, "obstacles travel as walls");
            assertArrayEquals(target.getGeometry(), objects[2].getGeometry());
            assertArrayEquals(home.getGeometry(), objects[3].getGeometry());
            assertEquals("A", ((RsNavNode) objects[4]).getLabel());
            assertEquals(Color.magenta, objects[4].fillColor);
            RsNavLink link2 = (RsNavLink) objects[6];
            assertSame(objects[4], link2.n0);
            assertSame(objects[5], link2.n1);
            assertEquals("road", link2.getLabel());
            assertArrayEquals(paint.getGeometry(), objects[7].getGeometry());
            assertEquals(Color.black, objects[7].fillColor);
            assertEquals(0, ((RsPaint) objects[7]).getRegion(), "region codes are not transmitted");
        }
    }

    @Test
    void theBodyOfSection13_3Is114BytesAfterAHandshake() throws Exception {
        RsBody body = new RsBody("B");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.15);
        c.setName("c");
        c.setFillColor(Color.white);
        c.setLineColor(null);
        body.addPart(c);
        ByteArrayOutputStream sent = new ByteArrayOutputStream();
        RsClient client = ClientEventLoopTest.quietClient();
        client.setInputOutputStreams(new ByteArrayInputStream(Hex.bytes("00000000 00000000 00000000 00000001 00000002")), sent);
        client.exchangeIntroductions();
        client.sendBodySpecification(body);
        byte[] all = sent.toByteArray();
        byte[] message = Arrays.copyOfRange(all, 20, all.length);
        assertEquals(114, message.length);
        assertEquals(Hex.of(Hex.bytes("00000000 00000000 00000000 00000002 00000005 0001 42 00000001 00000001 00000002"
                + " 0000000000000000 0000000000000000 3fc3333333333333 0001 63"
                + " 00000001 000000ff 000000ff 000000ff 00000000"
                + " 00000001 000000ff 000000c8 00000000 00000001 000000ff 000000c8 00000000")), Hex.of(message));
    }
}
