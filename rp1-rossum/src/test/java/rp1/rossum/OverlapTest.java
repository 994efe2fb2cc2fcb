package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
