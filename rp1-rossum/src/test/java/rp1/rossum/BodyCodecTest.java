package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The BODY_SPECIFICATION payload (protocol.md section 8). */
class BodyCodecTest {
    private static final double[] SQUARE = TestPlans.rect(-0.05, -0.05, 0.05, 0.05);

    private static byte[] hex(String s) {
        String h = s.replaceAll("\\s+", "");
        byte[] b = new byte[h.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(h.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    @Test
    void theWorkedExampleOfSection13_3ComesOutByteForByte() {
        RsBody body = new RsBody("B");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.15);
        c.setName("c");
        c.setFillColor(Color.white);
        c.setLineColor(null);
        body.addPart(c);
        byte[] expected = hex("0001 42  00000001  00000001  00000002"
                + "0000000000000000 0000000000000000 3fc3333333333333"
                + "0001 63"
                + "00000001 000000ff 000000ff 000000ff"
                + "00000000"
                + "00000001 000000ff 000000c8 00000000"
                + "00000001 000000ff 000000c8 00000000");
        assertEquals(94, expected.length);
        assertArrayEquals(expected, BodyCodec.encode(body));
    }

    /** A car with Ackerman steering: 0.5 m track, 1 m wheel base, 45 degrees at the inner wheel. */
    private static RsBody car() {
        RsBody body = new RsBody("car");
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        body.addPart(a);
        return body;
    }

    private static RsBody roundTrip(RsBody body) throws Exception {
        return BodyCodec.decode(BodyCodec.encode(body));
    }

    private static void assertSamePart(RsBodyPart sent, RsBodyPart got) {
        assertEquals(sent.getClass(), got.getClass());
        assertEquals(sent.getID(), got.getID());
        assertEquals(sent.getName(), got.getName());
        assertEquals(sent.getColdFillColor(), got.getColdFillColor());
        assertEquals(sent.getColdLineColor(), got.getColdLineColor());
        assertEquals(sent.getHotFillColor(), got.getHotFillColor());
        assertEquals(sent.getHotLineColor(), got.getHotLineColor());
        if (sent instanceof RsBodyShape) {
            assertArrayEquals(((RsBodyShape) sent).getOutlineVertices(), ((RsBodyShape) got).getOutlineVertices());
        }
    }

    @Test
    void shapesCirclesAndPaintersRoundTrip() throws Exception {
        RsBody body = new RsBody("shapes");
        RsBodyShape shape = new RsBodyShape(new double[] {0, 0, 0.3, 0, 0.2, 0.2}, 3);
        shape.setName("hull");
        shape.setHotLineColor(null);
        RsBodyCircle circle = new RsBodyCircle(0.1, -0.2, 0.15);
        circle.setFillColor(Color.blue);
        RsBodyPainter painter = new RsBodyPainter(SQUARE, 4);
        body.addPart(shape);
        body.addPart(circle);
        body.addPart(painter);
        RsBody got = roundTrip(body);
        assertEquals("shapes", got.getName());
        RsBodyPart[] parts = got.getBodyPartArray();
        assertSamePart(shape, parts[0]);
        assertSamePart(circle, parts[1]);
        assertSamePart(painter, parts[2]);
        RsBodyCircle c = (RsBodyCircle) parts[1];
        assertEquals(0.1, c.getXCenter());
        assertEquals(-0.2, c.getYCenter());
        assertEquals(0.15, c.getRadius());
    }

    @Test
    void sensorsRoundTripWithTheirParameters() throws Exception {
        RsBody body = new RsBody("sensors");
        RsBodyTargetSensor target = new RsBodyTargetSensor(SQUARE, 4, 0.1, 0.02, 0.3, 0.7, 2.5, 5, 6);
        RsBodyContactSensor contact = new RsBodyContactSensor(SQUARE, 4);
        RsBodyRangeSensor range = new RsBodyRangeSensor(SQUARE, 4, 0.2, -0.1, -0.4, 3.0, 10);
        RsBodyPaintSensor paint = new RsBodyPaintSensor(SQUARE, 4, 0.05, 0.06);
        paint.setRegionSensitivity(new int[] {1, 7});
        RsBodyPaintSensor anyPaint = new RsBodyPaintSensor(SQUARE, 4, 0, 0);
        for (RsBodyPart p : new RsBodyPart[] {target, contact, range, paint, anyPaint}) {
            body.addPart(p);
        }
        RsBodyPart[] parts = roundTrip(body).getBodyPartArray();
        assertSamePart(target, parts[0]);
        RsBodyTargetSensor t = (RsBodyTargetSensor) parts[0];
        assertArrayEquals(new double[] {0.1, 0.02, 0.3, 0.7, 2.5},
                new double[] {t.getXDetector(), t.getYDetector(), t.getSightAngle(), t.getWidth(), t.getMaxRange()});
        assertEquals(5, t.getNWidthBin());
        assertEquals(6, t.getNRangeBin());
        assertSamePart(contact, parts[1]);
        RsBodyRangeSensor r = (RsBodyRangeSensor) parts[2];
        assertSamePart(range, r);
        assertArrayEquals(new double[] {0.2, -0.1, -0.4, 3.0},
                new double[] {r.getXDetector(), r.getYDetector(), r.getSightAngle(), r.getMaxRange()});
        assertEquals(10, r.getNRangeBin());
        RsBodyPaintSensor p = (RsBodyPaintSensor) parts[3];
        assertSamePart(paint, p);
        assertEquals(0.06, p.getYDetector());
        assertArrayEquals(new int[] {1, 7}, p.getRegionSensitivity());
        assertNull(((RsBodyPaintSensor) parts[4]).getRegionSensitivity());
    }

    @Test
    void aDifferentialWheelSystemRoundTripsWithWheelsCastersAndEncoders() throws Exception {
        RsBody body = new RsBody("diff");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        ds.addEncodersToDefaultWheels(64);
        ds.addDefaultCasterWheel(-0.1, 0, 0.02, 0.01);
        ds.setFillColor(Color.darkGray);
        ds.setLineColor(Color.black);
        body.addPart(ds);
        RsBody got = roundTrip(body);
        RsDifferentialSteering g = (RsDifferentialSteering) got.wheelSystem;
        assertSamePart(ds, g);
        assertEquals(0.18, g.getTrackWidth());
        assertEquals(0.075, g.getDriveWheelRadius());
        RsWheel[] w = g.getWheels();
        assertEquals(3, w.length);
        for (int k = 0; k < 3; k++) {
            RsWheel sent = ds.getWheels()[k];
            assertEquals(ds.getID() + 1 + k, w[k].getID());
            assertArrayEquals(sent.getOutlineVertices(), w[k].getOutlineVertices());
            assertEquals(sent.getX(), w[k].getX());
            assertEquals(sent.getY(), w[k].getY());
            assertEquals(sent.getWheelRadius(), w[k].getWheelRadius());
            assertEquals(sent.getMaxAbsSteeringAngle(), w[k].getMaxAbsSteeringAngle());
            assertEquals(sent.getEncoderIntervalCount(), w[k].getEncoderIntervalCount());
        }
        assertInstanceOf(RsWheelCaster.class, w[2]);
        assertEquals(64, w[0].getEncoderIntervalCount());
    }

    @Test
    void receivedWheelsAreUnnamedAndTakeTheSystemsFillColourAsBothColours() throws Exception {
        RsBody body = new RsBody("colours");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        ds.setFillColor(Color.darkGray);
        ds.setLineColor(Color.black);
        body.addPart(ds);
        for (RsWheel w : roundTrip(body).wheelSystem.getWheels()) {
            assertEquals("Unnamed", w.getName());
            assertEquals(Color.darkGray, w.getColdFillColor());
            assertEquals(Color.darkGray, w.getColdLineColor());
        }
    }

    @Test
    void anAckermanSystemArrivesWithASmallerRederivedSteeringLimit() throws Exception {
        RsBody body = car();
        RsAckermanSteering a = (RsAckermanSteering) body.wheelSystem;
        RsAckermanSteering g = (RsAckermanSteering) roundTrip(body).wheelSystem;
        assertEquals(0.5, g.getTrackWidth());
        assertEquals(1.0, g.getWheelBase());
        assertEquals(false, g.isDualSteering());
        double sent = Math.atan(0.8);
        assertEquals(Math.atan(1.0 / (1.0 / Math.tan(sent) + 0.25)), g.getMaxAbsSteeringAngle(), 1e-12);
        assertTrue(g.getMaxAbsSteeringAngle() < a.getMaxAbsSteeringAngle());
        assertEquals(4, g.getWheels().length);
        assertEquals(a.getWheels()[2].getMaxAbsSteeringAngle(), g.getWheels()[2].getMaxAbsSteeringAngle());
    }

    /**
     * A body the simulator decoded, written again (into a recording) and read back, is the body the
     * simulator had: the Ackerman limit is not derived a second time. A replay of the ackerman demo
     * steered less tightly than the run it replayed, and ran into a wall the run had missed.
     */
    @Test
    void aDecodedAckermanSystemEncodesBackToTheBytesItCameFrom() throws Exception {
        byte[] sent = BodyCodec.encode(car());
        RsBody simulators = BodyCodec.decode(sent);
        assertArrayEquals(sent, BodyCodec.encode(simulators));
        RsAckermanSteering once = (RsAckermanSteering) simulators.wheelSystem;
        RsAckermanSteering replayed = (RsAckermanSteering) BodyCodec.decode(BodyCodec.encode(simulators)).wheelSystem;
        assertEquals(once.getMaxAbsSteeringAngle(), replayed.getMaxAbsSteeringAngle());
        assertEquals(once.getMinTurnRadius(), replayed.getMinTurnRadius());
    }

    @Test
    void aWheelAddedDirectlyToTheBodyTravelsAsAPlainShape() throws Exception {
        RsBody body = new RsBody("loose wheel");
        RsWheel w = new RsWheel(SQUARE, 4, 0, 0, 0.05);
        body.addPart(w);
        RsBodyPart got = roundTrip(body).getBodyPartArray()[0];
        assertEquals(RsBodyShape.class, got.getClass());
        assertArrayEquals(w.getOutlineVertices(), ((RsBodyShape) got).getOutlineVertices());
    }

    @Test
    void bodyArtAndBareActuatorsAreLeftOut() throws Exception {
        RsBody body = new RsBody("decorated");
        body.addPart(new RsBodyArt(SQUARE, 4));
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.1);
        body.addPart(c);
        body.addPart(new RsActuator());
        RsBodyPart[] parts = roundTrip(body).getBodyPartArray();
        assertEquals(1, parts.length);
        assertEquals(c.getID(), parts[0].getID());
    }

    @Test
    void aBodyWithNothingToSendIsRefusedNamingIt() {
        RsBody body = new RsBody("ghost");
        body.addPart(new RsBodyArt(SQUARE, 4));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> BodyCodec.encode(body));
        assertTrue(e.getMessage().contains("ghost"));
        assertThrows(IllegalArgumentException.class, () -> BodyCodec.encode(new RsBody("empty")));
    }

    @Test
    void nullNamesTravelAsEmptyStrings() throws Exception {
        RsBody body = new RsBody(null);
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.1);
        c.setName(null);
        body.addPart(c);
        RsBody got = roundTrip(body);
        assertEquals("", got.getName());
        assertEquals("", got.getBodyPartArray()[0].getName());
    }

    /** A circle record for part id 9 (no name, null colours). */
    private static String circleRecord() {
        return "00000009 00000002 0000000000000000 0000000000000000 3fc3333333333333 0000"
                + "00000000 00000000 00000000 00000000";
    }

    @Test
    void emptySlotsAndUndefinedPartsAreSkipped() throws Exception {
        RsBody got = BodyCodec.decode(hex("0000 00000003 ffffffff 00000004 00000000" + circleRecord()));
        assertEquals(1, got.getBodyPartArray().length);
        assertEquals(9, got.getBodyPartArray()[0].getID());
        assertNull(got.getBodyPartArray()[0].getColdFillColor());
    }

    /**
     * A body with nothing in it, or nothing but empty slots and undefined parts, is refused: no client
     * library sends one, and a robot of no parts could not even be recorded (its encoding refuses it).
     */
    @Test
    void aBodyWithoutAnyDefinedPartIsRefused() {
        RsProtocolException none = assertThrows(RsProtocolException.class, () -> BodyCodec.decode(hex("0000 00000000")));
        assertEquals("nParts: a body needs at least one part", none.getMessage());
        RsProtocolException undefined = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 00000002 ffffffff 00000004 00000000")));
        assertEquals("nParts: a body needs at least one part of a defined type (all 2 are undefined or empty)",
                undefined.getMessage());
    }

    @Test
    @Timeout(5)
    void anAbstractSensorRecordIsRefusedNamingThePartAndType() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 00000002" + circleRecord() + "00000005 00000004")));
        assertEquals("part[1].partType", e.getField());
        assertTrue(e.getMessage().contains("4"));
    }

    @Test
    @Timeout(5)
    void anUnknownPartTypeIsRefusedNamingThePartAndType() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 00000001 00000005 0000002a")));
        assertEquals("part[0].partType", e.getField());
        assertTrue(e.getMessage().contains("42"));
    }

    @Test
    @Timeout(5)
    void anOversizedPartCountIsRefused() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 7fffffff")));
        assertEquals("nParts", e.getField());
        RsProtocolException negative = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 ffffffff")));
        assertEquals("nParts", negative.getField());
    }

    @Test
    @Timeout(5)
    void anOversizedOutlineIsRefused() {
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 00000001 00000005 00000003 40000000")));
        assertEquals("part[0].outline count", e.getField());
    }

    @Test
    @Timeout(5)
    void anOversizedWheelCountIsRefused() {
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> BodyCodec.decode(hex(
                "0000 00000001 00000005 00000001 00000000 3fd0000000000000 3fb0000000000000 00100000")));
        assertEquals("part[0].nWheels", e.getField());
    }

    @Test
    @Timeout(5)
    void anOutlineWithoutVerticesIsAnEmptyShape() throws Exception {
        RsBody got = BodyCodec.decode(hex("0000 00000001 00000005 00000003 00000000 0000"
                + "00000000 00000000 00000000 00000000"));
        assertEquals(0, ((RsBodyShape) got.getBodyPartArray()[0]).getOutlineEdgeCount());
    }

    @Test
    @Timeout(5)
    void aColourComponentOutOfRangeIsRefusedNamingIt() {
        String badFill = "00000009 00000002 0000000000000000 0000000000000000 3fc3333333333333 0000"
                + "00000001 0000012c 00000000 00000000";
        RsProtocolException e = assertThrows(RsProtocolException.class,
                () -> BodyCodec.decode(hex("0000 00000001" + badFill)));
        assertEquals("part[0].fillColor red", e.getField());
    }

    /** A payload with every kind of record. */
    private static byte[] fullPayload() {
        RsBody body = new RsBody("full");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.18, 0.075);
        ds.addDefaultWheels(0.075, 0.03);
        ds.addEncodersToDefaultWheels(16);
        ds.addDefaultCasterWheel(-0.1, 0, 0.02, 0.01);
        RsBodyPaintSensor paint = new RsBodyPaintSensor(SQUARE, 4, 0, 0);
        paint.setRegionSensitivity(2);
        body.addPart(new RsBodyTargetSensor(SQUARE, 4, 0, 0, 0, 1, 1, 1, 1));
        body.addPart(new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 1, 1));
        body.addPart(new RsBodyContactSensor(SQUARE, 4));
        body.addPart(paint);
        body.addPart(new RsBodyPainter(SQUARE, 4));
        body.addPart(new RsBodyCircle(0, 0, 0.1));
        body.addPart(ds);
        body.addPart(new RsAckermanSteering(0.5, 1.0, 0.1, 0.5, true));
        return BodyCodec.encode(body);
    }

    @Test
    @Timeout(10)
    void everyTruncationOfAValidPayloadIsReportedAsAProtocolError() {
        byte[] full = fullPayload();
        for (int n = 0; n < full.length; n++) {
            byte[] cut = Arrays.copyOf(full, n);
            RsProtocolException e = assertThrows(RsProtocolException.class, () -> BodyCodec.decode(cut), "length " + n);
            assertTrue(e.getMessage().contains("ended"), e.getMessage());
        }
    }

    @Test
    @Timeout(20)
    void corruptedPayloadsDecodeOrFailOnlyWithAProtocolError() {
        byte[] full = fullPayload();
        Random random = new Random(42);
        for (int i = 0; i < 3000; i++) {
            byte[] bytes = full.clone();
            for (int k = 0; k < 1 + random.nextInt(3); k++) {
                bytes[random.nextInt(bytes.length)] = (byte) random.nextInt(256);
            }
            try {
                BodyCodec.decode(bytes);
            } catch (RsProtocolException expected) {
                assertTrue(expected.getField() != null);
            } catch (Exception other) {
                throw new AssertionError("corruption " + i + " failed with " + other, other);
            }
        }
    }
}
