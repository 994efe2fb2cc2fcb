package rp1demo.firefighter;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsTarget;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1demo.DemoRun;
import rp1demo.clientzero.ClientZero;
import rp1demo.navigation.Pose;

/** The fire fighter searching the contest arena for a candle. */
@Timeout(60)
class FireFighterTest {

    @Test
    void itFindsACandleAndStopsBeforeItWithinSensorRangeWithoutTouchingAWall() throws Exception {
        FfMain c = new FfMain();
        try (DemoRun run = DemoRun.start("contest.txt", c, c, c::getBody)) {
            run.waitUntil(() -> c.getFireFighter() != null && c.getFireFighter().isDone(), 30, "the end of the search");
            FireFighter.Candle candle = c.getFireFighter().getCandle();
            assertNotNull(candle, "found a candle; log:\n" + run.logText());

            List<RsMotionHaltedEvent> halts = run.events().events(RsMotionHaltedEvent.class);
            assertFalse(halts.stream().anyMatch(h -> h.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION),
                    "no collision; log:\n" + run.logText());
            RsMotionHaltedEvent last = halts.get(halts.size() - 1);
            RsTarget target = (RsTarget) run.simulation().getWorld().getPlan().getObjectByName(candle.name());
            assertEquals(target.x, candle.x(), 1e-6, "the sensor located the candle");
            assertEquals(target.y, candle.y(), 1e-6, "the sensor located the candle");
            Pose pose = new Pose(last.x, last.y, last.orientation);
            assertEquals(FfMain.STANDOFF, pose.distanceTo(target.x, target.y), 0.005, "stopped before the candle");
            assertEquals(0.0, pose.turnTowards(target.x, target.y), Math.toRadians(0.2), "facing it");

            List<RsTargetSensorEvent> sightings = run.events().events(RsTargetSensorEvent.class);
            RsTargetSensorEvent seen = sightings.get(sightings.size() - 1);
            assertTrue(seen.status, "the candle is in sight at the end");
            assertEquals(candle.name(), seen.getNameOfObjectDetected());
            assertTrue(seen.range < ClientZero.HEAD_RANGE, "within the sensor's range");
            assertTrue(run.simTime() < 120, "found within two minutes, not " + run.simTime() + " s");
        }
    }
}
