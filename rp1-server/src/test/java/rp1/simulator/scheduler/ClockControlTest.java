package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * The user's clock controls (the window's Run menu): pause, step and speed change how fast simulated
 * time passes against the wall clock, never what runs at which simulated time. Driven by a fake wall clock.
 */
class ClockControlTest {
    private final List<String> log = new ArrayList<>();
    private final long[] wallNanos = {0};

    private Task record(String name) {
        return t -> log.add(name + "@" + t);
    }

    private Scheduler paced(double speed) {
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], speed));
        s.begin();
        return s;
    }

    private Scheduler lockstep() {
        Scheduler s = new Scheduler(SimClock.lockstep(() -> wallNanos[0]));
        s.begin();
        return s;
    }

    private void wallSeconds(double seconds) {
        wallNanos[0] += Math.round(seconds * 1e9);
    }

    @Test
    void aPausedPacedClockHoldsSimulatedTimeWhileTheWallClockMovesAndGoesOnFromThereWhenResumed() {
        Scheduler s = paced(1.0);
        s.schedule(0.5, Scheduler.NORMAL, record("a"));
        wallSeconds(0.2);
        s.pause();
        assertTrue(s.isPaused());
        wallSeconds(10.0);
        assertFalse(s.runNext(), "a is due by the wall clock but time stands at the pause");
        assertEquals(0.2, s.now(), 1e-12);
        s.unpause();
        assertFalse(s.isPaused());
        assertEquals(0.2, s.now(), 1e-12, "no catching up with the paused wall time");
        wallSeconds(0.3);
        assertTrue(s.runNext());
        assertEquals(Arrays.asList("a@0.5"), log);
    }

    @Test
    void aPausedLockstepClockStopsBetweenTasksButAppliesInputsAtTheTimeItStands() {
        Scheduler s = lockstep();
        InputQueue inputs = new InputQueue(s);
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        s.schedule(2.0, Scheduler.NORMAL, record("b"));
        assertTrue(s.runNext());
        s.pause();
        inputs.submit(new Input() {
            @Override
            public int source() {
                return 1;
            }

            @Override
            public void apply(double time) {
                log.add("input@" + time);
            }
        });
        assertEquals(0, s.runUntilIdle());
        assertTrue(s.isIdle(), "nothing may run while paused");
        assertEquals(Arrays.asList("a@1.0", "input@1.0"), log);
        s.unpause();
        assertEquals(1, s.runUntilIdle());
        assertEquals("b@2.0", log.get(2));
    }

    @Test
    void aStepRunsTasksUpToOneIntervalOnThenStandsStillAgain() {
        Scheduler s = lockstep();
        for (int i = 1; i <= 10; i++) {
            s.schedule(0.05 * i, Scheduler.NORMAL, record("m" + i));
        }
        s.pause();
        assertEquals(0, s.runUntilIdle());
        s.step(0.1);
        assertEquals(2, s.runUntilIdle(), "the motion steps at 0.05 and 0.1");
        assertTrue(s.isPaused(), "paused again after the step");
        s.step(0.1);
        assertEquals(2, s.runUntilIdle());
        assertEquals(0.2, s.recordedTime(), 1e-12);
        s.unpause();
        assertEquals(6, s.runUntilIdle());
        assertEquals(10, log.size());
    }

    @Test
    void aPacedStepPassesAtTheClocksSpeedAndStopsExactlyOneIntervalOn() {
        Scheduler s = paced(1.0);
        s.schedule(0.07, Scheduler.NORMAL, record("a"));
        s.schedule(0.12, Scheduler.NORMAL, record("b"));
        wallSeconds(0.02);
        s.pause();
        wallSeconds(5.0);
        s.step(0.05);
        assertEquals(0.02, s.now(), 1e-12, "the step starts from where time stood");
        wallSeconds(0.03);
        assertEquals(0.05, s.now(), 1e-12);
        wallSeconds(1.0);
        assertEquals(1, s.runUntilIdle());
        assertEquals(0.07, s.now(), 1e-12, "one interval after the pause, and no further");
        assertEquals(Arrays.asList("a@0.07"), log);
    }

    @Test
    void aStepWhileRunningPausesFirst() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        s.schedule(1.5, Scheduler.NORMAL, record("b"));
        s.step(1.2);
        assertEquals(1, s.runUntilIdle());
        assertTrue(s.isPaused());
    }

    @Test
    void changingTheSpeedKeepsTimeMonotonicAndTheTaskTimes() {
        Scheduler s = paced(1.0);
        s.schedule(0.5, Scheduler.NORMAL, record("a"));
        s.schedule(3.0, Scheduler.NORMAL, record("b"));
        s.schedule(3.5, Scheduler.NORMAL, record("c"));
        wallSeconds(0.3);
        s.setSpeed(10.0);
        assertEquals(0.3, s.now(), 1e-12, "the new speed counts from where time is");
        wallSeconds(0.02);
        assertEquals(0.5, s.now(), 1e-12);
        assertEquals(1, s.runUntilIdle());
        s.setSpeed(Double.POSITIVE_INFINITY);
        assertTrue(s.isLockstep());
        assertEquals(1, s.runNext() ? 1 : 0, "max: b runs at once");
        assertEquals(3.0, s.now(), 1e-12);
        wallSeconds(100.0);
        s.setSpeed(1.0);
        assertFalse(s.isLockstep());
        assertEquals(3.0, s.now(), 1e-12, "back to paced from the time lockstep reached, not from the wall clock");
        wallSeconds(0.4);
        assertFalse(s.runNext());
        assertEquals(3.4, s.now(), 1e-12);
        wallSeconds(0.1);
        s.runUntilIdle();
        assertEquals(Arrays.asList("a@0.5", "b@3.0", "c@3.5"), log);
    }

    @Test
    void aRunStartedAtMaxCanBeSlowedDownFromWhereItIs() {
        Scheduler s = lockstep();
        s.schedule(2.0, Scheduler.NORMAL, record("a"));
        s.schedule(2.5, Scheduler.NORMAL, record("b"));
        assertTrue(s.runNext());
        wallSeconds(50.0);
        s.setSpeed(1.0);
        assertEquals(2.0, s.now(), 1e-12);
        assertFalse(s.runNext());
        wallSeconds(0.5);
        assertTrue(s.runNext());
        assertEquals(Arrays.asList("a@2.0", "b@2.5"), log);
    }

    @Test
    void aReplayStaysLockstepAndTheSpeedMustBePositive() {
        Scheduler s = new Scheduler(SimClock.replay());
        s.setSpeed(1.0);
        assertTrue(s.isLockstep());
        assertThrows(IllegalArgumentException.class, () -> s.setSpeed(0.0));
        assertThrows(IllegalArgumentException.class, () -> s.setSpeed(Double.NaN));
    }

    @Test
    void pauseAndTheInterlockHoldTheClockEachOnItsOwn() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        s.stopClock();
        s.pause();
        s.resumeClock();
        assertEquals(0, s.runUntilIdle(), "the interlock let go, the pause still holds");
        s.stopClock();
        s.unpause();
        assertEquals(0, s.runUntilIdle(), "the pause let go, the interlock still holds");
        s.resumeClock();
        assertEquals(1, s.runUntilIdle());
    }

    @Test
    void whatWaitsForIdlenessWaitsForThePauseToEnd() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        s.pause();
        s.whenIdle(() -> log.add("idle"));
        s.runUntilIdle();
        assertEquals(Arrays.asList(), log, "a paused run is not an idle one");
        s.unpause();
        s.runUntilIdle();
        assertEquals(Arrays.asList("a@1.0", "idle"), log);
    }
}
