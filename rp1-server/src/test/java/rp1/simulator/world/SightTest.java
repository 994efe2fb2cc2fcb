package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsPoint;
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

    /**
     * What the sensors look at lies in the box that sensing gathers walls and robots from: both ends of
     * each ray as the range sensor casts it, and each target sensor's disc, at any pose.
     */
    @Test
    void theBoxHoldsEveryRayAsTheSensorCastsItAndEveryTargetDisc() {
        double[] shape = {0.08, -0.01, 0.1, -0.01, 0.1, 0.01, 0.08, 0.01};
        RsBody body = new RsBody("looker");
        RsBodyRangeSensor ahead = new RsBodyRangeSensor(shape, 4, 0.1, 0.0, 0.0, 0.5, 1);
        RsBodyRangeSensor aside = new RsBodyRangeSensor(shape, 4, 0.05, 0.08, 1.3, 2.0, 1);
        RsBodyTargetSensor target = new RsBodyTargetSensor(shape, 4, -0.1, 0.02, 0.0, 1.0, 3.0, 1, 1);
        body.addPart(ahead);
        body.addPart(aside);
        body.addPart(target);
        Sight sight = new Sight(body);
        java.util.Random random = new java.util.Random(3);
        for (int i = 0; i < 10_000; i++) {
            RsTransform pose = new RsTransform((random.nextDouble() - 0.5) * 20, (random.nextDouble() - 0.5) * 2000,
                    (random.nextDouble() - 0.5) * 2000);
            double[] box = sight.box(pose).clone();
            for (RsBodyRangeSensor s : new RsBodyRangeSensor[] {ahead, aside}) {
                RsPoint from = pose.map(s.getXDetector(), s.getYDetector());
                double heading = pose.getTheta() + s.getSightAngle();
                assertInside(box, from.x, from.y);
                assertInside(box, from.x + s.getMaxRange() * Math.cos(heading), from.y + s.getMaxRange() * Math.sin(heading));
            }
            RsPoint centre = pose.map(target.getXDetector(), target.getYDetector());
            assertInside(box, centre.x - 3.0, centre.y - 3.0);
            assertInside(box, centre.x + 3.0, centre.y + 3.0);
        }
    }

    private static void assertInside(double[] box, double x, double y) {
        assertTrue(box[0] <= x && x <= box[2] && box[1] <= y && y <= box[3],
                "(" + x + ", " + y + ") in " + java.util.Arrays.toString(box));
    }
}
