package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Part ids (protocol.md section 8.6): one process-wide counter, and how decoding reproduces ids. */
class BodyPartIdTest {
    private static final double[] SQUARE = TestPlans.rect(0, 0, 0.1, 0.1);

    @Test
    void everyKindOfPartTakesTheNextIdInConstructionOrder() {
        RsBodyCircle circle = new RsBodyCircle(0, 0, 0.1);
        RsBodyContactSensor contact = new RsBodyContactSensor(SQUARE, 4);
        RsDifferentialSteering wheels = new RsDifferentialSteering(0.2, 0.05);
        RsBodyArt art = new RsBodyArt(SQUARE, 4);
        RsBodyPainter painter = new RsBodyPainter();
        int first = circle.getID();
        assertEquals(first + 1, contact.getID());
        assertEquals(first + 2, wheels.getID());
        assertEquals(first + 3, art.getID());
        assertEquals(first + 4, painter.getID());
    }

    @Test
    void setNextPartSerialNumberChoosesTheNextId() {
        RsBodyPart.setNextPartSerialNumber(700);
        assertEquals(700, new RsBodyShape(SQUARE, 4).getID());
        assertEquals(701, new RsBodyShape(SQUARE, 4).getID());
    }

    @Test
    void defaultWheelsFollowTheirWheelSystemLeftThenRight() {
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        RsWheel[] w = ds.getWheels();
        assertEquals(ds.getID() + 1, w[0].getID());
        assertEquals("left wheel", w[0].getName());
        assertEquals(ds.getID() + 2, w[1].getID());
        assertEquals("right wheel", w[1].getName());
    }

    @Test
    void encodersOfTheDefaultWheelsAreTheWheelsThemselves() {
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        RsEncoder[] e = ds.addEncodersToDefaultWheels(100);
        assertSame(ds.getWheels()[0], e[0]);
        assertSame(ds.getWheels()[1], e[1]);
        assertEquals(ds.getID() + 1, e[0].getID());
    }

    @Test
    void decodingGivesEveryPartTheTransmittedIdAndWheelsTheFollowingOnes() throws Exception {
        RsBody body = new RsBody("robot");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        RsBodyCircle chassis = new RsBodyCircle(0, 0, 0.15);
        body.addPart(chassis);
        body.addPart(ds);

        RsBody decoded = BodyCodec.decode(BodyCodec.encode(body));

        RsBodyPart[] parts = decoded.getBodyPartArray();
        assertEquals(chassis.getID(), parts[0].getID());
        assertEquals(ds.getID(), parts[1].getID());
        RsWheel[] w = decoded.wheelSystem.getWheels();
        assertEquals(ds.getID() + 1, w[0].getID());
        assertEquals(ds.getID() + 2, w[1].getID());
    }

    @Test
    void decodingDoesNotRewindTheProcessWideCounter() throws Exception {
        RsBodyPart.setNextPartSerialNumber(5);
        RsBody body = new RsBody("early");
        body.addPart(new RsBodyCircle(0, 0, 0.1));
        byte[] bytes = BodyCodec.encode(body);
        RsBodyPart.setNextPartSerialNumber(900);

        BodyCodec.decode(bytes);

        assertEquals(900, RsBodyPart.peekNextPartSerialNumber());
        assertEquals(900, new RsBodyShape(SQUARE, 4).getID());
    }

    @Test
    void wheelsBuiltAfterAnotherPartGetIdsTheSimulatorWillNotAgreeWith() throws Exception {
        RsBody body = new RsBody("late wheels");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        RsBodyCircle inBetween = new RsBodyCircle(0, 0, 0.15);
        ds.addDefaultWheels(0.075, 0.03);
        body.addPart(inBetween);
        body.addPart(ds);

        RsBody decoded = BodyCodec.decode(BodyCodec.encode(body));

        assertEquals(ds.getID() + 2, ds.getWheels()[0].getID());
        assertEquals(ds.getID() + 1, decoded.wheelSystem.getWheels()[0].getID());
        assertNotEquals(ds.getWheels()[0].getID(), decoded.wheelSystem.getWheels()[0].getID());
    }

    @Test
    void cloningABodyKeepsIdsAndTakesNoNewOnes() throws Exception {
        RsBody body = new RsBody("clone");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.1);
        body.addPart(c);
        int next = RsBodyPart.peekNextPartSerialNumber();
        RsBody copy = (RsBody) body.clone();
        assertEquals(c.getID(), copy.getBodyPartArray()[0].getID());
        assertEquals(next, RsBodyPart.peekNextPartSerialNumber());
    }

    @Test
    @Timeout(10)
    void partsBuiltOnSeveralThreadsAtOnceNeverShareAnId() throws Exception {
        Set<Integer> ids = ConcurrentHashMap.newKeySet();
        Runnable build = () -> {
            for (int i = 0; i < 2000; i++) {
                ids.add(new RsBodyShape(SQUARE, 4).getID());
            }
        };
        Thread a = new Thread(build);
        Thread b = new Thread(build);
        a.start();
        b.start();
        a.join();
        b.join();
        assertEquals(4000, ids.size());
    }

    @Test
    void decodingOnOneThreadDoesNotAffectIdsTakenOnAnother() throws Exception {
        int[] seen = new int[1];
        int expected = RsBodyPart.peekNextPartSerialNumber();
        RsBodyPart.beginDecodingIds(50000);
        try {
            Thread other = new Thread(() -> seen[0] = new RsBodyShape(SQUARE, 4).getID());
            other.start();
            other.join();
        } finally {
            RsBodyPart.endDecodingIds();
        }
        assertEquals(expected, seen[0]);
    }
}
