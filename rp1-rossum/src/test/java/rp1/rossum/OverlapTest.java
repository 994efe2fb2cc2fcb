package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** The placement clear test (behavior.md section 7). */
class OverlapTest {
    private static RsBody squareRobot() {
        RsBody b = new RsBody("square");
        b.addPart(new RsBodyShape(TestPlans.rect(-0.1, -0.1, 0.1, 0.1), 4));
        return b;
    }

    private static RsPlan wallFrom(double x0) {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "wall", x0, -1, x0 + 0.1, 1);
        return plan;
    }

    @Test
    void aPoseClearOfTheWallByMoreThanATenthOfAMillimetreIsClear() {
        assertEquals(false, squareRobot().checkForOverlap(wallFrom(1.0), TestPlans.pose(0.8998, 0, 0)));
    }

    @Test
    void aPoseWithinATenthOfAMillimetreIsNotClear() {
        assertEquals(true, squareRobot().checkForOverlap(wallFrom(1.0), TestPlans.pose(0.89995, 0, 0)));
    }

    @Test
    void aBodyCrossingAWallIsNotClear() {
        assertEquals(true, squareRobot().checkForOverlap(wallFrom(1.0), TestPlans.pose(1.0, 0, 0)));
    }

    @Test
    void aBodyEntirelyInsideAWallIsNotClear() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "block", -5, -5, 5, 5);
        assertEquals(true, squareRobot().checkForOverlap(plan, TestPlans.pose(0, 0, 0)));
    }

    @Test
    void aWallPostEntirelyInsideTheBodyIsNotClear() {
        RsPlan plan = new RsPlan();
        TestPlans.box(plan, "post", 1.0, 1.0, 1.02, 1.02);
        assertEquals(true, squareRobot().checkForOverlap(plan, TestPlans.pose(1.0, 1.0, 0.3)));
    }

    @Test
    void theTurnedBodyIsTested() {
        RsBody b = new RsBody("long");
        b.addPart(new RsBodyShape(TestPlans.rect(-0.5, -0.05, 0.5, 0.05), 4));
        RsPlan plan = wallFrom(0.3);
        assertEquals(true, b.checkForOverlap(plan, TestPlans.pose(0, 0, 0)));
        assertEquals(false, b.checkForOverlap(plan, TestPlans.pose(0, 0, Math.PI / 2)));
    }

    @Test
    void aBodyWithoutInteractiveShapesIsAlwaysClear() {
        RsBody b = new RsBody("wheels");
        RsDifferentialSteering ds = new RsDifferentialSteering(0.3, 0.05);
        ds.addDefaultWheels(0.05, 0.02);
        b.addPart(ds);
        b.addPart(new RsBodyArt(TestPlans.rect(-1, -1, 1, 1), 4));
        assertEquals(false, b.checkForOverlap(wallFrom(0.0), TestPlans.pose(0, 0, 0)));
    }

    @Test
    void everyInteractivePartCounts() {
        RsBody b = squareRobot();
        b.addPart(new RsBodyRangeSensor(TestPlans.rect(0.1, -0.01, 0.5, 0.01), 4, 0.1, 0, 0, 1, 1));
        assertEquals(true, b.checkForOverlap(wallFrom(0.45), TestPlans.pose(0, 0, 0)));
    }

    /**
     * Walls far from the body are passed over by their boxes; the answers must be those of testing
     * every wall in full. Bodies of random outlines at random headings are put beside a wall with the
     * gap between their boxes drawn from a micrometre to ten centimetres, on either side of the
     * clearance and of the twice-the-clearance the boxes are compared with, or overlapping.
     */
    @Test
    void passingOverFarWallsByTheirBoxesChangesNoAnswer() {
        Random random = new Random(7);
        int overlapping = 0;
        int clear = 0;
        int clearWithinTwiceTheClearance = 0;
        for (int trial = 0; trial < 20_000; trial++) {
            int n = 3 + random.nextInt(10);
            double[] points = new double[2 * n];
            for (int i = 0; i < n; i++) {
                double angle = 2 * Math.PI * (i + 0.8 * random.nextDouble()) / n;
                double radius = 0.05 + 0.25 * random.nextDouble();
                points[2 * i] = radius * Math.cos(angle);
                points[2 * i + 1] = radius * Math.sin(angle);
            }
            RsBody body = new RsBody("random");
            RsBodyShape shape = new RsBodyShape(points, n);
            body.addPart(shape);
            RsPlan plan = new RsPlan();
            double wx = 10 * random.nextDouble();
            double wy = 10 * random.nextDouble();
            TestPlans.box(plan, "wall", wx, wy, wx + 0.05 + random.nextDouble(), wy + 0.05 + random.nextDouble());
            TestPlans.box(plan, "far", wx + 3, wy + 3, wx + 4, wy + 4);
            double theta = 2 * Math.PI * random.nextDouble();
            double[] box = boxOf(BodyOutline.map(shape.collisionOutline(), TestPlans.pose(0, 0, theta)));
            double gap = (random.nextInt(4) == 0 ? -1 : 1) * Math.pow(10, -6 + 5 * random.nextDouble());
            // The body's box just left of the wall's box, or just below it, by the gap.
            boolean left = random.nextBoolean();
            double x = left ? wx - box[2] - gap : wx + 0.05 * random.nextDouble() - box[0];
            double y = left ? wy + 0.05 * random.nextDouble() - box[1] : wy - box[3] - gap;
            RsTransform pose = TestPlans.pose(x, y, theta);
            boolean expected = everyWallInFull(shape, plan.getWallArray(), pose);
            assertEquals(expected, body.checkForOverlap(plan, pose), "trial " + trial);
            if (expected) {
                overlapping++;
            } else {
                clear++;
                if (Math.abs(gap) < 2e-4) {
                    clearWithinTwiceTheClearance++;
                }
            }
        }
        assertTrue(overlapping > 2_000 && clear > 2_000 && clearWithinTwiceTheClearance > 100,
                overlapping + " overlapping, " + clear + " clear, " + clearWithinTwiceTheClearance + " of them near");
    }

    /** The placement test as it was before the boxes: every edge, every vertex, of every wall. */
    private static boolean everyWallInFull(RsBodyShape shape, RsWall[] walls, RsTransform pose) {
        RsSegment[] body = BodyOutline.map(shape.collisionOutline(), pose);
        RsSegSect sect = new RsSegSect();
        for (RsWall wall : walls) {
            RsSegment[] edges = wall.getSegmentArray();
            for (RsSegment b : body) {
                for (RsSegment w : edges) {
                    if (sect.process(b, w)) {
                        return true;
                    }
                }
                if (wall.getPolygon().checkContainment(b.x, b.y, 1e-4) != RsPolygon.OUTSIDE) {
                    return true;
                }
            }
            for (RsSegment w : edges) {
                if (BodyOutline.insideOrNear(body, w.x, w.y, 1e-4)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static double[] boxOf(RsSegment[] edges) {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (RsSegment e : edges) {
            b[0] = Math.min(b[0], e.x);
            b[1] = Math.min(b[1], e.y);
            b[2] = Math.max(b[2], e.x);
            b[3] = Math.max(b[3], e.y);
        }
        return b;
    }
}
