package rp1demo.ackerman;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1demo.navigation.Pose;

class CourseDriverTest {
    private static final double MAX = Math.toRadians(30);

    @Test
    void onTheCourseItSteersStraightAndToTheRightOfItItSteersLeftWithinTheLimit() {
        CourseDriver d = new CourseDriver(new double[] {0, 0, 10, 0}, 0.6, 1.0, 1.0, MAX, s -> { });
        assertEquals(0.0, d.steer(new Pose(0, 0, 0)).angle(), 1e-12);
        double left = d.steer(new Pose(1, -0.3, 0)).angle();
        assertTrue(left > 0 && left <= MAX, "steers back left: " + left);
        assertEquals(MAX, d.steer(new Pose(2, -0.2, -1.5)).angle(), 1e-12, "limited");
        assertEquals(2.0, d.progress(), 1e-9);
    }

    @Test
    void itReportsCornersAndFinishesAtTheEndEvenWhereTheCourseEndsWhereItBegan() {
        List<String> said = new ArrayList<>();
        CourseDriver d = new CourseDriver(new double[] {0, 0, 2, 0, 2, 2, 0, 0}, 0.6, 1.0, 1.0, MAX, said::add);
        assertTrue(d.steer(new Pose(0, 0, 0)) != null, "not done at the start, although the end is there too");
        d.steer(new Pose(1.5, 0, 0));
        d.steer(new Pose(2, 1, Math.PI / 2));
        d.steer(new Pose(2, 2, Math.PI));
        d.steer(new Pose(1, 1, -2.3));
        assertNull(d.steer(new Pose(0.05, 0.05, -2.3)));
        assertTrue(d.isFinished());
        assertEquals(List.of("Passing corner 1 of 2 at (2.0, 0.0)", "Passing corner 2 of 2 at (2.0, 2.0)"),
                said.subList(0, 2));
    }

    @Test
    void aCourseNeedsTwoPoints() {
        assertThrows(IllegalArgumentException.class, () -> new CourseDriver(new double[] {1, 2}, 0.6, 1, 1, MAX, s -> { }));
    }
}
