package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.awt.Color;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTarget;

/**
 * Our syntax sampler (planparser/sampler.txt), which uses every construct found in the RP1 0.60
 * sample plans: comments holding code, quotes and line comments; tokens packed without spaces;
 * walls; an obstacle given by vertices, moved and turned by a non-right angle; a regular-polygon
 * obstacle with separate fill and line colours; a target; placements with a negative orientation
 * and without a label; an unclosed paint polygon spread over lines; nodes and links. Every value
 * is worked out here by hand (behavior.md section 1), within 1e-9.
 */
class SamplerPlanTest {
    private static final double EPS = 1e-9;
    private final RsPlan plan = TestPlans.parse(TestPlans.sampler());

    @Test
    void captionUnitsAndObjectsInDeclarationOrder() {
        assertEquals("Syntax Sampler", plan.getCaption());
        assertEquals("meters", plan.getUnits().getName());
        assertArrayEquals(new String[] {"south", "slant", "wedge", "post", "lamp", "dock", "mark", "pad", "n1", "n2",
            "hub", "a1", "a2"}, plan.getObjects().stream().map(RsObject::getName).toArray());
    }

    @Test
    void wallsAreRectanglesAroundTheirCentreLines() {
        assertGeometry("south", 0, -0.02, 4, -0.02, 4, 0.02, 0, 0.02);
        double h = 0.01 / Math.sqrt(2);
        assertGeometry("slant", 1 - h, 3 - h, 3 - h, 1 - h, 3 + h, 1 + h, 1 + h, 3 + h);
        assertColours("slant", Color.lightGray, Color.darkGray);
    }

    @Test
    void anObstacleGivenByVerticesIsTurnedAboutTheOriginThenMoved() {
        double c = Math.cos(Math.toRadians(30));
        double s = Math.sin(Math.toRadians(30));
        assertGeometry("wedge", 2, 2.5, 2 + 0.6 * c, 2.5 + 0.6 * s, 2 - 0.3 * s, 2.5 + 0.3 * c);
    }

    @Test
    void aRegularPolygonObstacleStartsOnPlusXAndTakesItsTwoColours() {
        double[] hexagon = new double[12];
        for (int k = 0; k < 6; k++) {
            hexagon[2 * k] = 3.5 + 0.2 * Math.cos(k * Math.PI / 3);
            hexagon[2 * k + 1] = 3.0 + 0.2 * Math.sin(k * Math.PI / 3);
        }
        assertGeometry("post", hexagon);
        assertColours("post", Color.yellow, Color.blue);
    }

    @Test
    void targetAndPlacementsKeepLabelColourAndLineWidth() {
        RsTarget lamp = (RsTarget) plan.getObjectByName("lamp");
        assertGeometry("lamp", 0.5, 3.5, 0.1);
        assertEquals("L", lamp.label);
        assertColours("lamp", Color.red, Color.red);
        assertEquals(3, lamp.lineWidth);
        RsPlacement dock = (RsPlacement) plan.getObjectByName("dock");
        assertGeometry("dock", 3.6, 0.4, -Math.PI / 6, 0.2);
        assertEquals("D", dock.label);
        assertColours("dock", Color.green, Color.green);
        RsPlacement mark = (RsPlacement) plan.getObjectByName("mark");
        assertGeometry("mark", 1.5, 0.5, 0.0, 0.05);
        assertNull(mark.label);
        assertColours("mark", Color.white, Color.white);
        assertEquals(6, mark.lineWidth);
    }

    @Test
    void anUnclosedPaintPolygonIsClosed() {
        RsPaint pad = (RsPaint) plan.getObjectByName("pad");
        assertGeometry("pad", 0.8, 1.6, 0.8, 2.0, 1.2, 2.0, 1.2, 1.6, 0.8, 1.6);
        assertEquals(4, pad.getSegmentArray().length);
        assertEquals(3, pad.getRegion());
        assertColours("pad", Color.black, Color.black);
    }

    @Test
    void nodesAndLinksFormTheNetwork() {
        assertGeometry("n1", 0.5, 0.5);
        assertGeometry("n2", 2.25, 0.5);
        assertGeometry("hub", 2.25, 1.75);
        assertEquals("N2", ((RsNavNode) plan.getObjectByName("n2")).getLabel());
        assertColours("hub", Color.cyan, Color.cyan);
        RsNavLink a2 = (RsNavLink) plan.getObjectByName("a2");
        assertSame(plan.getObjectByName("n2"), a2.n0);
        assertSame(plan.getObjectByName("hub"), a2.n1);
        assertNull(a2.getLabel());
        assertEquals(2, ((RsNavNode) plan.getObjectByName("n2")).link.length);
        assertEquals(1, ((RsNavNode) plan.getObjectByName("hub")).link.length);
    }

    @Test
    void theExtentRunsFromTheSouthWallToTheTopOfTheLampsRing() {
        RsRectangle b = plan.getBounds();
        assertArrayEquals(new double[] {0, -0.02, 4, 3.62}, new double[] {b.x, b.y, b.width, b.height}, EPS);
    }

    private void assertGeometry(String name, double... expected) {
        assertArrayEquals(expected, plan.getObjectByName(name).getGeometry(), EPS, name);
    }

    private void assertColours(String name, Color fill, Color line) {
        assertEquals(fill, plan.getObjectByName(name).fillColor, name + " fill");
        assertEquals(line, plan.getObjectByName(name).lineColor, name + " line");
    }
}
