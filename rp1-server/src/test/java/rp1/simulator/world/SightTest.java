package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsTransform;

/** Which robots a range sensor could see follows the robot as it turns, though its rays are kept per pose. */
class SightTest {
    @Test
    void aRobotAheadIsSeenOnlyWhileTheSensorFacesIt() {
        RsBody body = new RsBody("looker");
        body.addPart(new RsBodyRangeSensor(new double[] {0.08, -0.01, 0.1, -0.01, 0.1, 0.01, 0.08, 0.01}, 4, 0.1, 0.0,
                0.0, 0.5, 1));
        Sight sight = new Sight(body);
        RsTransform east = new RsTransform(0.0, 1.0, 1.0);
        RsTransform north = new RsTransform(Math.PI / 2, 1.0, 1.0);
        assertTrue(sight.mightSee(east, 1.4, 1.0, 0.1));
        assertFalse(sight.mightSee(east, 1.0, 1.4, 0.1));
        assertTrue(sight.mightSee(north, 1.0, 1.4, 0.1));
        assertFalse(sight.mightSee(north, 1.4, 1.0, 0.1));
        east.copy(north);
        assertFalse(sight.mightSee(east, 1.4, 1.0, 0.1), "the same transform object, turned, is a new pose");
    }
}
