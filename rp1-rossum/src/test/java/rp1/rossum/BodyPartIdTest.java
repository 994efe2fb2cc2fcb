package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Part ids (protocol.md section 8.6): every body numbers its parts from 1 in construction order, the
 * first time an id is needed; decoding reproduces the sender's ids.
 */
class BodyPartIdTest {
    private static final double[] SQUARE = TestPlans.rect(0, 0, 0.1, 0.1);

    /** ClientZero's way: the wheel system built first but added last, a sensor in between. */
    private static RsBody clientZero() {
        RsBody body = new RsBody("zero");
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        RsBodyCircle chassis = new RsBodyCircle(0, 0, 0.15);
        chassis.setName("chassis");
        body.addPart(chassis);
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(SQUARE, 4, 0.1, 0.0, 0.0, 1.0, 10);
        sonar.setName("sonar");
        body.addPart(sonar);
        body.addPart(drive);
        return body;
    }

    private static int[] ids(RsBody body) {
        return body.allParts().stream().mapToInt(RsBodyPart::getID).toArray();
    }

    @Test
    void aBodysPartsAreNumberedFromOneInConstructionOrderAsByRp1sCounterInAFreshProcess() {
        RsBody body = clientZero();
        assertArrayEquals(new int[] {4, 5, 1, 2, 3}, new int[] {
            body.getPartByName("chassis").getID(), body.getPartByName("sonar").getID(),
            body.wheelSystem.getID(), body.wheelSystem.getWheels()[0].getID(), body.wheelSystem.getWheels()[1].getID()});
    }

    @Test
    void everyBodyIsNumberedAlikeWhateverWasBuiltBefore() {
        int[] first = ids(clientZero());
        for (int i = 0; i < 50; i++) {
            new RsBodyCircle(0, 0, 0.1).getID();
        }
        assertArrayEquals(first, ids(clientZero()));
    }

    @Test
    void anIdOnceReadNeverChanges() {
        RsBody body = new RsBody("late parts");
        RsBodyCircle first = new RsBodyCircle(0, 0, 0.1);
        body.addPart(first);
        assertEquals(1, first.getID());
        RsBodyShape later = new RsBodyShape(SQUARE, 4);
        body.addPart(later);
        assertEquals(1, first.getID());
        assertEquals(2, later.getID());
    }

    @Test
    void aWheelSystemInNoBodyNumbersItselfAndItsWheels() {
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        RsWheel[] w = ds.getWheels();
        assertEquals(1, ds.getID());
        assertEquals(2, w[0].getID());
        assertEquals("left wheel", w[0].getName());
        assertEquals(3, w[1].getID());
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
        RsBody body = clientZero();
        RsBodyPart sonar = body.getPartByName("sonar");
        sonar.assignID(40);

        RsBody decoded = BodyCodec.decode(BodyCodec.encode(body));

        assertArrayEquals(ids(body), ids(decoded));
        assertEquals(40, decoded.getPartByName("sonar").getID());
        RsWheel[] w = decoded.wheelSystem.getWheels();
        assertEquals(decoded.wheelSystem.getID() + 1, w[0].getID());
        assertEquals(decoded.wheelSystem.getID() + 2, w[1].getID());
    }

    @Test
    void aDecodedIdOfZeroStaysZero() throws Exception {
        RsBody body = new RsBody("zero id");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.1);
        c.assignID(0);
        body.addPart(c);
        RsBody decoded = BodyCodec.decode(BodyCodec.encode(body));
        decoded.addPart(new RsBodyCircle(0, 0, 0.2));
        assertEquals(0, decoded.getBodyPartArray()[0].getID());
        assertEquals(1, decoded.getBodyPartArray()[1].getID());
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
    void cloningABodyKeepsIds() throws Exception {
        RsBody body = clientZero();
        int[] before = ids(body);
        RsBody copy = (RsBody) body.clone();
        assertArrayEquals(before, ids(copy));
    }

    @Test
    void theOldCounterSetterChangesNothing() {
        RsBodyPart.setNextPartSerialNumber(700);
        assertEquals(1, new RsBodyShape(SQUARE, 4).getID());
    }

    @Test
    @Timeout(10)
    void bodiesBuiltOnSeveralThreadsAtOnceAreNumberedAlike() throws Exception {
        AtomicReference<int[]> other = new AtomicReference<>();
        Thread t = new Thread(() -> {
            int[] last = null;
            for (int i = 0; i < 200; i++) {
                last = ids(clientZero());
            }
            other.set(last);
        });
        t.start();
        int[] mine = null;
        for (int i = 0; i < 200; i++) {
            mine = ids(clientZero());
        }
        t.join();
        assertArrayEquals(mine, other.get());
    }

    @Test
    void aBodyIsNumberedByTheClientThatSendsItTheSameOnBothEnds() throws Exception {
        RsBody first = clientZero();
        RsBody second = clientZero();
        assertEquals(0, first.getID(), "not sent yet");
        try (Link link = Link.piped(ClientEventLoopTest.quietClient(), new RsConnection())) {
            ServerRecorder server = new ServerRecorder(link.connection);
            link.startServer();
            link.client.sendBodySpecification(first);
            link.client.sendBodySpecification(second);
            assertEquals(1, ((RsBody) server.received.next()).getID());
            assertEquals(2, ((RsBody) server.received.next()).getID());
        }
        assertEquals(1, first.getID());
        assertEquals(2, second.getID());
    }
}
