package rp1demo.navigation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PoseTest {

    @Test
    void robotFrameTurnsAndNormalizedAngles() {
        Pose p = new Pose(1, 1, Math.PI / 2);
        double[] r = p.toRobotFrame(1, 3);
        assertEquals(2.0, r[0], 1e-12, "ahead");
        assertEquals(0.0, r[1], 1e-12);
        assertEquals(Math.PI / 2, p.turnTowards(0, 1), 1e-12, "to the left");
        assertEquals(Math.PI, Pose.normalize(-Math.PI), 1e-12);
        assertEquals(-0.5, Pose.normalize(2 * Math.PI - 0.5), 1e-12);
    }

    @Test
    void theLogShowsTheHeadingAsTheWindowDoesFrom0To360() {
        assertEquals("(2.500, 2.500) heading 225.0 deg", new Pose(2.5, 2.5, Math.toRadians(225)).toString());
        assertEquals("(2.500, 2.500) heading 225.0 deg", new Pose(2.5, 2.5, Math.toRadians(-135)).toString());
        assertEquals("(0.000, 0.000) heading 270.0 deg", new Pose(0, 0, Math.toRadians(-450)).toString());
    }
}
