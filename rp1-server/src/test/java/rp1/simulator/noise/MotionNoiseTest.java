package rp1.simulator.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.request.RsMotionRequest;

/** Wheel slip: the motion made differs from the one commanded, the robot believes the commanded one. */
class MotionNoiseTest {
    private static final int N = 50_000;

    private static MotionNoise slip(double distance, double turn) {
        return new MotionNoise(new NoiseSettings(0, 0, 0, 0, 0, distance, turn), 31L, 1);
    }

    @Test
    void distanceAndTurnSlipInProportionWithTheirOwnSigmas() {
        MotionNoise m = slip(0.05, 0.2);
        double distanceSquares = 0;
        double turnSquares = 0;
        for (int i = 0; i < N; i++) {
            RsMotionRequest made = m.slip(new RsMotionRequest(0.4, 0.5, 1.0));
            assertEquals(1.0, made.duration);
            distanceSquares += Math.pow(made.linearVelocity / 0.4 - 1.0, 2);
            turnSquares += Math.pow(made.rotationalVelocity / 0.5 - 1.0, 2);
        }
        assertEquals(0.05, Math.sqrt(distanceSquares / N), 0.001);
        assertEquals(0.2, Math.sqrt(turnSquares / N), 0.004);
    }

    @Test
    void motionEventsReportTheCommandedMotionFromWhereTheRobotWasPlaced() {
        MotionNoise m = slip(0.3, 0.3);
        m.placed(0.0, 1.0, 2.0, 0.0);
        m.begin(0.0, new RsMotionRequest(0.5, 0.0, 4.0));
        RsMotionStartedEvent s = m.started(new RsMotionStartedEvent(0.0, 0.5, 0.0, 4.0, 9, 9, 9));
        assertEquals(1.0, s.x, 1e-12);
        assertEquals(2.0, s.y, 1e-12);
        assertEquals(0.5, s.linearVelocity);
        RsMotionHaltedEvent h = m.halted(new RsMotionHaltedEvent(4.0, RsMotionHaltedEvent.HALTED_ON_COMPLETION,
                9, 9, 9, 4.0));
        assertEquals(3.0, h.x, 1e-12);
        assertEquals(2.0, h.y, 1e-12);
        assertEquals(0.0, h.orientation, 1e-12);
    }

    @Test
    void aMotionStoppedEarlyIsBelievedToHaveRunOnlyUntilThen() {
        MotionNoise m = slip(0.3, 0.3);
        m.placed(0.0, 0.0, 0.0, 0.0);
        m.begin(0.0, new RsMotionRequest(1.0, 0.0, 10.0));
        RsMotionHaltedEvent h = m.halted(new RsMotionHaltedEvent(2.0, RsMotionHaltedEvent.HALTED_ON_COLLISION,
                9, 9, 9, 2.0));
        assertEquals(2.0, h.x, 1e-12);
        m.begin(5.0, new RsMotionRequest(0.0, Math.PI / 2, 1.0));
        RsMotionStartedEvent s = m.started(new RsMotionStartedEvent(5.0, 0.0, Math.PI / 2, 1.0, 9, 9, 9));
        assertEquals(2.0, s.x, 1e-12);
        assertEquals(2.0, m.believedPose(6.0).m13, 1e-12);
        assertEquals(Math.PI / 2, m.believedPose(6.0).getTheta(), 1e-12);
    }
}
