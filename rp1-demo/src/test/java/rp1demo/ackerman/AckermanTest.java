package rp1demo.ackerman;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsPoint;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1demo.DemoRun;

/** The Ackerman car driving its lap around the cones of ackerman.txt. */
@Timeout(60)
class AckermanTest {

    /** The extremes of where the car's rear axle went. */
    private static final class Extent {
        private double minX = Double.POSITIVE_INFINITY;
        private double maxX = Double.NEGATIVE_INFINITY;
        private double maxY = Double.NEGATIVE_INFINITY;
        private double nearestToCone3 = Double.POSITIVE_INFINITY;

        synchronized void sample(RsPoint p) {
            minX = Math.min(minX, p.x);
            maxX = Math.max(maxX, p.x);
            maxY = Math.max(maxY, p.y);
            nearestToCone3 = Math.min(nearestToCone3, Math.hypot(p.x - 8.0, p.y - 4.0));
        }
    }

    @Test
    void itDrivesRoundTheConesAndBackNearHomeWithoutTouchingAnything() throws Exception {
        Main c = new Main();
        try (DemoRun run = DemoRun.start("ackerman.txt", c, c, c::getBody)) {
            Extent extent = new Extent();
            run.watchRobot(pose -> extent.sample(pose.getOffset()));
            RsMotionHaltedEvent parked = run.events().await(RsMotionHaltedEvent.class, e -> true, 30);

            assertEquals(RsMotionHaltedEvent.HALTED_ON_REQUEST, parked.causeOfHalt, "stopped by the driver; log:\n" + run.logText());
            assertTrue(c.getDriver().isFinished());
            assertEquals(2.5, parked.x, 0.4, "back near home");
            assertEquals(4.0, parked.y, 0.4, "back near home");
            assertTrue(Math.abs(parked.orientation) < Math.toRadians(30), "heading east again");
            synchronized (extent) {
                assertTrue(extent.maxX > 8.9, "went round the east side of the third cone: " + extent.maxX);
                assertTrue(extent.maxY > 6.5, "came back north of the second cone: " + extent.maxY);
                assertTrue(extent.minX < 1.3, "turned round in the west: " + extent.minX);
                assertTrue(extent.nearestToCone3 > 0.8, "kept clear of the third cone: " + extent.nearestToCone3);
            }
            List<RsMotionHaltedEvent> halts = run.events().events(RsMotionHaltedEvent.class);
            assertFalse(halts.stream().anyMatch(h -> h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION));
            assertTrue(parked.simTime < 40, "about 21 m at 1 m/s, not " + parked.simTime + " s");
        }
    }
}
