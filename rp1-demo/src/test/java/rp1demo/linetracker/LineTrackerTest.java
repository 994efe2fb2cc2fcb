package rp1demo.linetracker;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsPoint;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1demo.DemoRun;
import rp1demo.navigation.Pose;

/**
 * The line tracker on linetrack.txt, whose line is a 2 cm band around a stadium: straights from
 * x = 0.45 to 1.05 at y = 0.2 and 0.8 joined by half circles of 0.3 m radius, i.e. the points 0.3 m
 * from the segment (0.45, 0.5)-(1.05, 0.5). The robot starts on the bottom straight facing east.
 */
@Timeout(60)
class LineTrackerTest {
    private static final double CENTRE_X = 0.75;
    private static final double CENTRE_Y = 0.5;

    /** Samples the robot's pose at every motion step: the angle swept around the loop's centre and
     * how far the eyes stray from the middle of the line. */
    private static final class Lap {
        private double swept;
        private double lastAngle = Double.NaN;
        private double worstStray;

        synchronized void sample(RsTransform pose) {
            RsPoint p = pose.getOffset();
            double a = Math.atan2(p.y - CENTRE_Y, p.x - CENTRE_X);
            if (!Double.isNaN(lastAngle)) {
                swept += Pose.normalize(a - lastAngle);
            }
            lastAngle = a;
            RsPoint eyes = pose.map(LineTracker.EYE_X, 0.0);
            worstStray = Math.max(worstStray, Math.abs(distanceToSpine(eyes.x, eyes.y) - 0.3));
        }

        synchronized double swept() {
            return swept;
        }

        synchronized double worstStray() {
            return worstStray;
        }

        private static double distanceToSpine(double x, double y) {
            double cx = Math.max(0.45, Math.min(1.05, x));
            return Math.hypot(x - cx, y - CENTRE_Y);
        }
    }

    @Test
    void itCompletesALapWithoutLosingTheLine() throws Exception {
        LtMain c = new LtMain();
        try (DemoRun run = DemoRun.start("linetrack.txt", c, c, c::getBody)) {
            Lap lap = new Lap();
            run.watchRobot(lap::sample);
            run.waitUntil(() -> lap.swept() > 2.0 * Math.PI + 0.2, 30, "a full lap");
            run.simulation().shutdown();

            assertTrue(run.simTime() < 60, "a 3.1 m lap at about 0.15 m/s, not " + run.simTime() + " s");
            assertTrue(lap.worstStray() < 0.012, "the eyes stayed over the line; worst stray " + lap.worstStray());
            assertEquals(0, c.getFollower().timesLost(), "never lost the line; log:\n" + run.logText());
            assertFalse(run.events().events(RsMotionHaltedEvent.class).stream()
                    .anyMatch(h -> h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION));
            assertTrue(longestTimeBothEyesOff(run, c) < 0.25, "the eyes never both left the line for long");
        }
    }

    /** The longest stretch of simulated time during which neither eye saw the line. */
    private static double longestTimeBothEyesOff(DemoRun run, LtMain c) {
        int left = ((RsBodyPaintSensor) c.getBody().getPartByName(LineTracker.LEFT_EYE)).getID();
        boolean leftOn = true;
        boolean rightOn = true;
        double lostSince = Double.NaN;
        double longest = 0.0;
        List<RsPaintSensorEvent> events = run.events().events(RsPaintSensorEvent.class);
        for (RsPaintSensorEvent e : events) {
            if (e.sensorID == left) {
                leftOn = e.status;
            } else {
                rightOn = e.status;
            }
            if (!leftOn && !rightOn && Double.isNaN(lostSince)) {
                lostSince = e.simTime;
            } else if ((leftOn || rightOn) && !Double.isNaN(lostSince)) {
                longest = Math.max(longest, e.simTime - lostSince);
                lostSince = Double.NaN;
            }
        }
        return longest;
    }
}
