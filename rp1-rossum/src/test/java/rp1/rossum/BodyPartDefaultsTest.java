package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.Color;
import org.junit.jupiter.api.Test;

/** Default names and colours of every part kind (protocol.md section 8.5). */
class BodyPartDefaultsTest {
    private static final double[] SQUARE = TestPlans.rect(0, 0, 0.1, 0.1);
    private static final Color LIGHT_GRAY = new Color(192, 192, 192);
    private static final Color ORANGE = new Color(255, 200, 0);
    private static final Color RED = new Color(255, 0, 0);

    @Test
    void namesDefaultByKind() {
        assertEquals("Unnamed", new RsBodyShape(SQUARE, 4).getName());
        assertEquals("Unnamed Circle", new RsBodyCircle(0, 0, 1).getName());
        assertEquals("Unnamed Target Sensor", new RsBodyTargetSensor(SQUARE, 4, 0, 0, 0, 0, 1, 1, 1).getName());
        assertEquals("Unnamed Contact Sensor", new RsBodyContactSensor(SQUARE, 4).getName());
        assertEquals("Unnamed Range Sensor", new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 1, 1).getName());
        assertEquals("Unnamed Paint Sensor", new RsBodyPaintSensor(SQUARE, 4, 0, 0).getName());
        assertEquals("Differential Steering", new RsDifferentialSteering(1, 1).getName());
        assertEquals("Ackerman Steering", new RsAckermanSteering(1, 1, 1, 0.5, false).getName());
        assertEquals("Actuator", new RsActuator().getName());
        assertEquals("Unnamed", new RsBodyPainter().getName());
    }

    @Test
    void partsAreLightGrayWithOrangeHotColours() {
        RsBodyShape s = new RsBodyShape(SQUARE, 4);
        assertEquals(LIGHT_GRAY, s.getFillColor());
        assertEquals(LIGHT_GRAY, s.getLineColor());
        assertEquals(ORANGE, s.getHotFillColor());
        assertEquals(ORANGE, s.getHotLineColor());
    }

    @Test
    void sensorsHaveARedHotLine() {
        RsBodySensor s = new RsBodyContactSensor(SQUARE, 4);
        assertEquals(ORANGE, s.getHotFillColor());
        assertEquals(RED, s.getHotLineColor());
    }

    @Test
    void colourGettersGiveTheHotVariantWhileHot() {
        RsBodyShape s = new RsBodyShape(SQUARE, 4);
        s.setFillColor(Color.blue);
        s.setHotFillColor(Color.green);
        s.setHotLineColor(null);
        s.setHot(true);
        assertEquals(Color.green, s.getFillColor());
        assertNull(s.getLineColor());
        assertEquals(Color.blue, s.getColdFillColor());
        s.setHot(false);
        assertEquals(Color.blue, s.getFillColor());
        assertEquals(LIGHT_GRAY, s.getLineColor());
    }

    @Test
    void wheelSystemColoursReachItsWheels() {
        RsDifferentialSteering ds = new RsDifferentialSteering(0.2, 0.05);
        ds.addDefaultWheels(0.05, 0.02);
        ds.setFillColor(Color.darkGray);
        ds.setLineColor(Color.black);
        for (RsWheel w : ds.getWheels()) {
            assertEquals(Color.darkGray, w.getFillColor());
            assertEquals(Color.black, w.getLineColor());
        }
    }

    @Test
    void casterHasNoRadiusAndTurnsAllTheWayRound() {
        RsWheelCaster c = new RsWheelCaster(SQUARE, 4, 0.05, 0.05);
        assertEquals(0.0, c.getWheelRadius());
        assertEquals(2 * Math.PI, c.getMaxAbsSteeringAngle());
        assertEquals(true, c.isWheelSteerable());
    }

    @Test
    void wheelFromTheFiveArgumentConstructorDoesNotSteer() {
        RsWheel w = new RsWheel(SQUARE, 4, 0.05, 0.05, 0.05);
        assertEquals(0.0, w.getMaxAbsSteeringAngle());
        assertEquals(false, w.isWheelSteerable());
    }

    @Test
    void rangeSensorClampsItsRangeAndBins() {
        RsBodyRangeSensor r = new RsBodyRangeSensor(SQUARE, 4, 0, 0, 0, 5.0e6, 0);
        assertEquals(1.0e6, r.getMaxRange());
        assertEquals(1, r.getNRangeBin());
        assertEquals(-1, r.getRangeBin());
    }

    @Test
    void painterDefaultsAndTrailerDefinition() {
        RsBodyPainter p = new RsBodyPainter(SQUARE, 4);
        assertEquals(0.01, p.getTrailerMinimumSegmentLength());
        assertEquals(0.0, p.getTrailerWidth());
        assertEquals(false, p.isTrailerDefined());
        assertNull(p.getPaintColors());
        p.setTrailerWidth(-2.0);
        assertEquals(0.0, p.getTrailerWidth());
        assertEquals(true, p.isTrailerDefined());
        p.setPaintColor(Color.red);
        assertEquals(1, p.getPaintColors().length);
        p.setPainterActivationStatus(true);
        assertEquals(true, p.getHot());
        p.removeTrailer();
        assertEquals(false, p.isTrailerDefined());
    }

    @Test
    void painterTrailerPositionDefinesTheTrailer() {
        RsBodyPainter p = new RsBodyPainter();
        p.setTrailerPosition(-0.1, 0.02);
        assertEquals(true, p.isTrailerDefined());
        assertEquals(-0.1, p.getTrailerX());
        assertEquals(0.02, p.getTrailerY());
    }

    @Test
    void paintSensorWithAnEmptySensitivityListSensesEveryRegion() {
        RsBodyPaintSensor s = new RsBodyPaintSensor(SQUARE, 4, 0, 0);
        s.setRegionSensitivity(new int[0]);
        assertNull(s.getRegionSensitivity());
        s.setRegionSensitivity(3);
        assertEquals(3, s.getRegionSensitivity()[0]);
    }
}
