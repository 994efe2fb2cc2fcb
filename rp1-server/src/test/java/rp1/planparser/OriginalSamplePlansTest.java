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
import rp1.rossum.RsWall;

/**
 * The floor plans shipped with RP1 0.60 parse into the objects behavior.md section 11 describes. Every
 * expected value is stated here, in metres (inches divided by 39.3696), within 1e-9.
 */
class OriginalSamplePlansTest {
    private static final double EPS = 1e-9;
    private static final double IN = 39.3696;
    private static final Color ORANGE = new Color(255, 200, 0);

    /** The corners of a wall: P0 - n, P1 - n, P1 + n, P0 + n with n the half-thickness normal (section 1.7). */
    static double[] wallCorners(double x0, double y0, double x1, double y1, double t, double scale) {
        double dx = (x1 - x0) / scale;
        double dy = (y1 - y0) / scale;
        double len = Math.hypot(dx, dy);
        double nx = -dy * (t / scale) / 2 / len;
        double ny = dx * (t / scale) / 2 / len;
        double ax = x0 / scale;
        double ay = y0 / scale;
        double bx = x1 / scale;
        double by = y1 / scale;
        return new double[] {ax - nx, ay - ny, bx - nx, by - ny, bx + nx, by + ny, ax + nx, ay + ny};
    }

    static void assertNames(RsPlan plan, String... names) {
        assertArrayEquals(names, plan.getObjects().stream().map(RsObject::getName).toArray());
    }

    static void assertBounds(RsPlan plan, double x, double y, double w, double h) {
        RsRectangle b = plan.getBounds();
        assertArrayEquals(new double[] {x, y, w, h}, new double[] {b.x, b.y, b.width, b.height}, EPS);
    }

    static void assertWall(RsPlan plan, String name, double[] corners) {
        RsWall w = (RsWall) plan.getObjectByName(name);
        assertArrayEquals(corners, w.getGeometry(), EPS, name);
        assertEquals(Color.lightGray, w.fillColor);
        assertEquals(Color.darkGray, w.lineColor);
    }

    static void assertPoint(RsObject o, double[] geometry, String label, Color color, int lineWidth) {
        assertArrayEquals(geometry, o.getGeometry(), EPS, o.getName());
        assertEquals(label, o.label, o.getName());
        assertEquals(color, o.fillColor, o.getName());
        assertEquals(color, o.lineColor, o.getName());
        int width = o instanceof RsTarget ? ((RsTarget) o).lineWidth : ((RsPlacement) o).lineWidth;
        assertEquals(lineWidth, width, o.getName());
    }

    @Test
    void whiteRoom() {
        RsPlan plan = TestPlans.parse(TestPlans.original("WhiteRoom.txt"));
        assertEquals("White Room (RP1 rev. 0.4)", plan.getCaption());
        assertEquals("meters", plan.getUnits().getName());
        assertNames(plan, "a", "b", "c", "d", "e", "goal", "home");
        assertWall(plan, "a", new double[] {0, -0.025, 3, -0.025, 3, 0.025, 0, 0.025});
        assertWall(plan, "b", new double[] {3.025, 0, 3.025, 3, 2.975, 3, 2.975, 0});
        assertWall(plan, "c", wallCorners(3, 3, 0, 3, 0.05, 1));
        assertWall(plan, "d", wallCorners(0, 3, 0, 0, 0.05, 1));
        assertWall(plan, "e", wallCorners(1, 2, 2, 1, 0.025, 1));
        assertPoint(plan.getObjectByName("goal"), new double[] {0.4, 0.4, 0.25}, "Goal", Color.red, 3);
        assertPoint(plan.getObjectByName("home"), new double[] {2.5, 2.5, 3.9269908169872414, 0.275}, "Home",
                Color.green, 3);
        assertBounds(plan, -0.025, -0.025, 3.05, 3.05);
    }

    @Test
    void ackerman() {
        RsPlan plan = TestPlans.parse(TestPlans.original("ackerman.txt"));
        assertEquals("Test Plan for Ackerman", plan.getCaption());
        assertEquals("meters", plan.getUnits().getName());
        assertNames(plan, "a", "b", "c", "d", "home");
        assertWall(plan, "a", wallCorners(0, 0, 5, 0, 0.02, 1));
        assertWall(plan, "b", wallCorners(5, 0, 5, 5, 0.02, 1));
        assertWall(plan, "c", wallCorners(5, 5, 0, 5, 0.02, 1));
        assertWall(plan, "d", wallCorners(0, 5, 0, 0, 0.02, 1));
        assertPoint(plan.getObjectByName("home"), new double[] {2.5, 2.5, Math.PI, 0.2}, "H", Color.green, 3);
        assertBounds(plan, -0.01, -0.01, 5.02, 5.02);
    }

    @Test
    void fourCorners() {
        RsPlan plan = TestPlans.parse(TestPlans.original("test.txt"));
        assertEquals("Four Corners", plan.getCaption());
        assertNames(plan, "a", "b", "c", "d", "x", "y", "pa", "pb", "pc", "pd");
        assertWall(plan, "d", wallCorners(0, 3, 0, 0, 0.05, 1));
        double c = Math.cos(Math.toRadians(15));
        double s = Math.sin(Math.toRadians(15));
        double[] triangle = {1, 1, 1 + c, 1 + s, 1 + 0.5 * c - 0.866 * s, 1 + 0.5 * s + 0.866 * c};
        assertWall(plan, "x", triangle);
        double[] hexagon = new double[12];
        for (int k = 0; k < 6; k++) {
            hexagon[2 * k] = 0.5 + 0.25 * Math.cos(k * Math.PI / 3);
            hexagon[2 * k + 1] = 2.25 + 0.25 * Math.sin(k * Math.PI / 3);
        }
        RsWall y = (RsWall) plan.getObjectByName("y");
        assertArrayEquals(hexagon, y.getGeometry(), EPS);
        assertEquals(ORANGE, y.fillColor);
        assertEquals(Color.red, y.lineColor);
        double[][] poses = {{0.2, 0.2, 45}, {2.84, 0.16, 135}, {2.5, 2.5, 225}, {0.16, 2.84, -45}};
        String[] names = {"pa", "pb", "pc", "pd"};
        for (int i = 0; i < 4; i++) {
            double[] g = {poses[i][0], poses[i][1], Math.toRadians(poses[i][2]), 0.15};
            assertPoint(plan.getObjectByName(names[i]), g, String.valueOf((char) ('A' + i)), Color.green, 3);
        }
        assertBounds(plan, -0.025, -0.025, 3.05, 3.05);
    }

    @Test
    void trinityContest() {
        RsPlan plan = TestPlans.parse(TestPlans.original("trinity2001.txt"));
        assertEquals("Fire-Fighting Robot Contest -- April 22, 2001", plan.getCaption());
        assertEquals("inches", plan.getUnits().getName());
        assertEquals(51, plan.getObjectCount());
        double[][] walls = {{0, 0, 98, 0}, {98, 0, 98, 98}, {98, 98, 0, 98}, {0, 98, 0, 0}, {0, 51, 31, 51},
            {31, 51, 31, 18}, {49, 0, 49, 17}, {49, 35, 98, 35}, {31, 98, 31, 73}, {31, 73, 18, 73},
            {49, 80, 49, 56}, {49, 56, 80, 56}, {80, 56, 80, 80}, {80, 80, 70.5, 80}};
        RsWall[] wallArray = plan.getWallArray();
        assertEquals(14, wallArray.length);
        for (int i = 0; i < walls.length; i++) {
            double[] w = walls[i];
            assertEquals(String.valueOf((char) ('a' + i)), wallArray[i].getName());
            assertWall(plan, wallArray[i].getName(), wallCorners(w[0], w[1], w[2], w[3], 0.75, IN));
        }
        double[][] candles = {{15, 39}, {71.4, 65.15}, {87.1, 10.9}, {23.1, 82.3}};
        RsTarget[] targets = plan.getTargetArray();
        assertEquals(4, targets.length);
        for (int i = 0; i < 4; i++) {
            String name = "F" + (i + 1);
            assertEquals(name, targets[i].getName());
            assertPoint(targets[i], new double[] {candles[i][0] / IN, candles[i][1] / IN, 6 / IN}, name, Color.red, 3);
        }
        assertPoint(plan.getObjectByName("home"), new double[] {89.8 / IN, 46.0 / IN, Math.PI, 6 / IN}, "H",
                Color.green, 3);
        assertTrinityNetwork(plan);
        assertBounds(plan, -0.375 / IN, -0.375 / IN, 98.75 / IN, 98.75 / IN);
    }

    private static void assertTrinityNetwork(RsPlan plan) {
        Object[][] nodes = {{"n0", 13.0, 11.0, "n0"}, {"n1", 40.0, 11.0, "n1"}, {"CheckPoint3", 70.0, 20.0, "ChkPt3"},
            {"n3", 40.0, 26.0, "n3"}, {"n4", 61.0, 26.0, "n4"}, {"CheckPoint0", 13.0, 25.5, "ChkPt0"},
            {"n6", 40.0, 46.0, "n6"}, {"n7", 89.8, 46.0, "n7"}, {"n8", 9.0, 64.0, "n8"}, {"n9", 40.0, 64.0, "n9"},
            {"n10", 59.5, 77.75, "n10"}, {"CheckPoint2", 64.25, 70.0, "ChkPt2"}, {"CheckPoint1", 9.0, 89.0, "ChlPt1"},
            {"n12", 40.0, 89.0, "n12"}, {"n13", 56.0, 89.0, "n13"}, {"n14", 89.8, 89.0, "n14"}};
        RsNavNode[] nodeArray = plan.getNavNodeArray();
        assertEquals(nodes.length, nodeArray.length);
        for (int i = 0; i < nodes.length; i++) {
            RsNavNode n = nodeArray[i];
            assertEquals(nodes[i][0], n.getName());
            assertArrayEquals(new double[] {(Double) nodes[i][1] / IN, (Double) nodes[i][2] / IN}, n.getGeometry(), EPS);
            assertEquals(nodes[i][3], n.getLabel());
            assertEquals(Color.cyan, n.lineColor);
        }
        String[][] links = {{"p0", "n0", "n1"}, {"p1", "n0", "CheckPoint0"}, {"p2", "n1", "n3"}, {"p3", "n3", "n4"},
            {"p4", "n4", "CheckPoint3"}, {"p5", "n3", "n6"}, {"p6", "n6", "n7"}, {"p7", "n7", "n14"},
            {"p8", "n6", "n9"}, {"p9", "n9", "n8"}, {"p10", "n8", "CheckPoint1"}, {"p11", "n9", "n12"},
            {"p12", "n12", "n13"}, {"p13", "n10", "n13"}, {"p14", "n10", "CheckPoint2"}, {"p17", "n13", "n14"}};
        RsNavLink[] linkArray = plan.getNavLinkArray();
        assertEquals(links.length, linkArray.length);
        for (int i = 0; i < links.length; i++) {
            assertEquals(links[i][0], linkArray[i].getName());
            assertSame(plan.getObjectByName(links[i][1]), linkArray[i].n0);
            assertSame(plan.getObjectByName(links[i][2]), linkArray[i].n1);
            assertNull(linkArray[i].getLabel());
        }
        assertEquals(3, ((RsNavNode) plan.getObjectByName("n3")).link.length);
        assertEquals(1, ((RsNavNode) plan.getObjectByName("CheckPoint2")).link.length);
    }

    @Test
    void lineTrack() {
        RsPlan plan = TestPlans.parse(TestPlans.original("LineTrack.txt"));
        assertEquals("Simple Line-Tracing Test Plan", plan.getCaption());
        assertEquals("meters", plan.getUnits().getName());
        assertNames(plan, "a", "b", "c", "d", "startLine", "outsideTrack", "insideTrack", "finish1");
        assertWall(plan, "a", wallCorners(-0.125, -0.125, -0.125, 0.875, 0.019, 1));
        assertWall(plan, "c", wallCorners(1.125, 0.875, 1.125, -0.125, 0.019, 1));
        assertPoint(plan.getObjectByName("startLine"), new double[] {0.35, 0, 0, 0.05}, null, Color.white, 6);
        assertPaint(plan, "outsideTrack", 114, 1, Color.black, new double[] {0.875, -0.0095}, new double[] {0.25, -0.0095});
        assertPaint(plan, "insideTrack", 114, 2, Color.white, new double[] {0.875, 0.0095}, new double[] {0.25, 0.0095});
        RsPaint finish = (RsPaint) plan.getObjectByName("finish1");
        assertArrayEquals(new double[] {0.245, -0.043, 0.245, 0.043, 0.33, 0.043, 0.33, -0.043, 0.245, -0.043},
                finish.getGeometry(), EPS);
        assertEquals(1, finish.getRegion());
        assertBounds(plan, -0.1345, -0.1345, 1.269, 1.019);
    }

    private static void assertPaint(RsPlan plan, String name, int vertices, int region, Color color, double[] first,
            double[] last) {
        RsPaint p = (RsPaint) plan.getObjectByName(name);
        assertEquals(vertices, p.getSegmentArray().length, name);
        assertEquals(region, p.getRegion(), name);
        assertEquals(color, p.fillColor, name);
        assertEquals(color, p.lineColor, name);
        double[] g = p.getGeometry();
        assertArrayEquals(first, new double[] {g[0], g[1]}, EPS, name);
        assertArrayEquals(last, new double[] {g[g.length - 4], g[g.length - 3]}, EPS, name);
    }
}
