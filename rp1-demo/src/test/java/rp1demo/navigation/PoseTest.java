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
}
