package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import rp1.rossum.request.RsMotionRequest;

/** The body as a container of parts, its state copies and its drawing. */
class BodyTest {
    private static final double[] SQUARE = TestPlans.rect(-0.05, -0.05, 0.05, 0.05);

    @Test
    void addingNullIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new RsBody("b").addPart(null));
    }

    @Test
    void partsKeepTheirOrderAndAWheelSystemBecomesTheBodysWheelSystem() {
        RsBody b = new RsBody("b");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.1);
        RsDifferentialSteering ds = new RsDifferentialSteering(0.2, 0.05);
        RsBodyPainter p = new RsBodyPainter(SQUARE, 4);
        b.addPart(ds);
        b.addPart(c);
        b.addPart(p);
        assertArrayEquals(new RsBodyPart[] {ds, c, p}, b.getBodyPartArray());
        assertSame(ds, b.wheelSystem);
        assertArrayEquals(new RsBodyPainter[] {p}, b.getBodyPainterArray());
    }

    @Test
    void theSensorListIsTheSensorArrayAndFollowsPartsAddedLater() {
        RsBody b = new RsBody("b");
        RsBodyRangeSensor range = new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 1, 1);
        b.addPart(new RsBodyShape(SQUARE, 4));
        b.addPart(range);
        assertEquals(List.of(range), b.getBodySensors());
        assertThrows(UnsupportedOperationException.class, () -> b.getBodySensors().clear());
        RsBodyContactSensor contact = new RsBodyContactSensor(SQUARE, 4);
        b.addPart(contact);
        assertEquals(List.of(range, contact), b.getBodySensors());
        assertArrayEquals(b.getBodySensorArray(), b.getBodySensors().toArray());
    }

    @Test
    void interactiveShapesAreShapesSensorsAndPaintersOnly() {
        RsBody b = new RsBody("b");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.2, 0.05);
        ds.addDefaultWheels(0.05, 0.02);
        RsBodyShape shape = new RsBodyShape(SQUARE, 4);
        RsBodyRangeSensor range = new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 1, 1);
        RsBodyPainter painter = new RsBodyPainter(SQUARE, 4);
        RsBodyCircle circle = new RsBodyCircle(0, 0, 1);
        b.addPart(ds);
        b.addPart(shape);
        b.addPart(new RsBodyArt(SQUARE, 4));
        b.addPart(range);
        b.addPart(new RsWheel(SQUARE, 4, 0, 0, 0.05));
        b.addPart(painter);
        b.addPart(circle);
        assertArrayEquals(new RsBodyShape[] {shape, range, painter, circle}, b.getInteractiveBodyShapeArray());
    }

    @Test
    void partsAreFoundByNameAndIdIncludingWheels() {
        RsBody b = new RsBody("b");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.2, 0.05);
        ds.addDefaultWheels(0.05, 0.02);
        RsBodyTargetSensor head = new RsBodyTargetSensor(SQUARE, 4, 0, 0, 0, 1, 1, 1, 1);
        head.setName("head");
        b.addPart(head);
        b.addPart(ds);
        assertSame(head, b.getPartByName("head"));
        assertSame(ds.getWheels()[1], b.getPartByName("right wheel"));
        assertSame(ds.getWheels()[0], b.getPartByID(ds.getID() + 1));
        assertSame(ds.getWheels()[0], ds.getWheelForID(ds.getID() + 1));
        assertNull(b.getPartByName("tail"));
        assertNull(b.getPartByID(-5));
    }

    @Test
    void boundsFollowThePose() {
        RsBody b = new RsBody("b");
        b.addPart(new RsBodyShape(TestPlans.rect(0, -0.1, 0.4, 0.1), 4));
        b.place(0.0, 1.0, 2.0, Math.PI / 2);
        RsRectangle r = b.getBounds();
        assertEquals(0.9, r.x, 1e-9);
        assertEquals(2.0, r.y, 1e-9);
        assertEquals(0.2, r.width, 1e-9);
        assertEquals(0.4, r.height, 1e-9);
        assertEquals(4, b.getRefEnclosure().length);
    }

    @Test
    void aPlacementResetsSteeringButNotSensorsOrEncoders() {
        RsBody b = new RsBody("b");
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, 0.5, false);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        RsBodyContactSensor bumper = new RsBodyContactSensor(SQUARE, 4);
        bumper.setHot(true);
        b.addPart(a);
        b.addPart(bumper);
        a.setSteeringAngle(0.2);
        b.place(0.0, 1, 1, 0);
        assertEquals(0.0, a.getSteeringAngle());
        assertEquals(true, bumper.getHot());
        assertEquals(true, b.getPlacement());
    }

    @Test
    void aCopyOfTheBodyTakesOverTheOriginalsState() throws Exception {
        RsBody b = new RsBody("b");
        RsBodyTargetSensor eye = new RsBodyTargetSensor(SQUARE, 4, 0, 0, 0, 0, 5, 1, 1);
        b.addPart(eye);
        RsBody copy = (RsBody) b.clone();
        RsPlan plan = new RsPlan();
        TestPlans.target(plan, "t", 1, 0);
        b.place(0.0, 0, 0, 0);
        b.computeMotion(0.0, new RsMotionRequest(1, 0, 1));
        b.motion.setTime(0.5);
        b.processSensors(0.5, plan, b.motion.transform);
        copy.copyStateData(b);
        assertEquals(true, copy.getBodyPartArray()[0].getHot());
        assertEquals(0.5, copy.getMotion().getPosition().x, 1e-12);
        assertEquals(true, copy.getPlacement());
        b.motion.setTime(1.0);
        assertEquals(0.5, copy.getMotion().getPosition().x, 1e-12);
    }

    @Test
    void aBodyWithEvaluatedSensorsCanBeCloned() throws Exception {
        RsBody b = new RsBody("b");
        RsBodyRangeSensor r = new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 5, 4);
        b.addPart(r);
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "w", 1, -1, 2, 1);
        r.computeAndSetState(0.0, plan, TestPlans.pose(0, 0, 0));
        RsBody copy = (RsBody) b.clone();
        RsBodySensor copied = (RsBodySensor) copy.getBodyPartArray()[0];
        assertEquals("w", copied.getSensorEvent(0.0).getNameOfObjectDetected());
    }

    /** Draws the body on a 100 x 100 image with 100 pixels per metre, origin at the centre. */
    private static BufferedImage draw(RsBody b) {
        BufferedImage image = new BufferedImage(100, 100, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.white);
        g.fillRect(0, 0, 100, 100);
        RsTransform view = new RsTransform();
        view.m11 = 100;
        view.m22 = -100;
        view.m13 = 50;
        view.m23 = 50;
        b.paint(g, view);
        g.dispose();
        return image;
    }

    @Test
    void partsAreFilledInTheirColourAndHotPartsInTheirHotColour() {
        RsBody b = new RsBody("b");
        RsBodyShape s = new RsBodyShape(TestPlans.rect(-0.2, -0.2, 0.2, 0.2), 4);
        s.setFillColor(Color.blue);
        s.setHotFillColor(Color.red);
        b.addPart(s);
        b.place(0.0, 0, 0, 0);
        assertEquals(Color.blue.getRGB(), draw(b).getRGB(50, 50));
        s.setHot(true);
        assertEquals(Color.red.getRGB(), draw(b).getRGB(50, 50));
    }

    @Test
    void aNullColourIsNotDrawn() {
        RsBody b = new RsBody("b");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.3);
        c.setFillColor(null);
        c.setLineColor(null);
        b.addPart(c);
        assertEquals(Color.white.getRGB(), draw(b).getRGB(50, 50));
        assertEquals(Color.white.getRGB(), draw(b).getRGB(80, 50));
    }

    @Test
    void aCircleIsDrawnAsATrueCircle() {
        RsBody b = new RsBody("b");
        RsBodyCircle c = new RsBodyCircle(0, 0, 0.3);
        c.setFillColor(Color.green);
        c.setLineColor(Color.green);
        b.addPart(c);
        BufferedImage image = draw(b);
        assertEquals(Color.green.getRGB(), image.getRGB(50, 21));
        assertEquals(Color.white.getRGB(), image.getRGB(28, 28));
    }

    @Test
    void laterPartsAreDrawnOnTop() {
        RsBody b = new RsBody("b");
        RsBodyShape under = new RsBodyShape(TestPlans.rect(-0.2, -0.2, 0.2, 0.2), 4);
        under.setFillColor(Color.blue);
        RsBodyShape over = new RsBodyShape(TestPlans.rect(-0.1, -0.1, 0.1, 0.1), 4);
        over.setFillColor(Color.yellow);
        b.addPart(under);
        b.addPart(over);
        assertEquals(Color.yellow.getRGB(), draw(b).getRGB(50, 50));
    }

    @Test
    void steeredWheelsAreDrawnTurned() {
        RsBody b = new RsBody("b");
        RsAckermanSteering a = new RsAckermanSteering(0.0, 0.0, 0.1, 0.5, false);
        RsWheel w = new RsWheel(TestPlans.rect(-0.3, -0.05, 0.3, 0.05), 4, 0, 0, 0.3, Math.PI);
        w.setFillColor(Color.black);
        a.addWheel(w);
        b.addPart(a);
        assertEquals(Color.black.getRGB(), draw(b).getRGB(75, 50));
        w.setOrientation(Math.PI / 2);
        BufferedImage turned = draw(b);
        assertEquals(Color.white.getRGB(), turned.getRGB(75, 50));
        assertEquals(Color.black.getRGB(), turned.getRGB(50, 25));
    }

    @Test
    void bodyArtIsDrawnAsALine() {
        RsBody b = new RsBody("b");
        RsBodyArt art = new RsBodyArt(new double[] {-0.3, 0, 0.3, 0}, 2);
        art.setLineColor(Color.magenta);
        b.addPart(art);
        assertEquals(Color.magenta.getRGB(), draw(b).getRGB(60, 50));
        art.transform(Math.PI / 2, 1.0, 0.0, 0.0);
        assertEquals(Color.magenta.getRGB(), draw(b).getRGB(50, 40));
    }
}
