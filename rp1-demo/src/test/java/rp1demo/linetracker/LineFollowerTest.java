package rp1demo.linetracker;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import rp1demo.linetracker.LineFollower.Eye;
import rp1demo.linetracker.LineFollower.WheelSpeeds;

class LineFollowerTest {

    @Test
    void itSteersTowardsTheEyeStillOnTheLineAndSearchesTowardsTheSideLastSeen() {
        LineFollower f = new LineFollower(0.3);
        assertEquals(new WheelSpeeds(0.3, 0.3), f.command(), "both eyes on: straight on");
        WheelSpeeds right = f.sensed(Eye.RIGHT, false);
        assertTrue(right.right() > right.left() && right.left() > 0, "right eye off: curve left, " + right);
        WheelSpeeds lost = f.sensed(Eye.LEFT, false);
        assertTrue(lost.left() < 0 && lost.right() > 0, "both off, the left saw it last: turn left on the spot, " + lost);
        assertEquals(1, f.timesLost());
        WheelSpeeds back = f.sensed(Eye.RIGHT, true);
        assertTrue(back.left() > back.right() && back.right() > 0, "only the right eye on: curve right, " + back);
        f.sensed(Eye.RIGHT, false);
        WheelSpeeds lostRight = f.command();
        assertTrue(lostRight.left() > 0 && lostRight.right() < 0, "lost again, the right saw it last, " + lostRight);
        assertEquals(2, f.timesLost());
    }

    @Test
    void aCruiseSpeedMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new LineFollower(0.0));
    }
}
