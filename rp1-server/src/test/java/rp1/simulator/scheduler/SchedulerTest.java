package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Task order and simulation time, driven step by step without threads. */
class SchedulerTest {
    private final List<String> log = new ArrayList<>();

    private Task record(String name) {
        return t -> log.add(name + "@" + t);
    }

    private static Scheduler lockstep() {
        Scheduler s = new Scheduler(SimClock.lockstep());
        s.startClock();
        return s;
    }

    @Test
    void tasksRunByTimeThenPriorityThenInsertionOrder() {
        Scheduler s = lockstep();
        s.schedule(2.0, Scheduler.NORMAL, record("b"));
        s.schedule(1.0, Scheduler.HEARTBEAT, record("heartbeat"));
        s.schedule(1.0, Scheduler.NORMAL, record("timeout1"));
        s.schedule(1.0, Scheduler.NORMAL, record("timeout2"));
        s.schedule(0.5, Scheduler.NORMAL, record("a"));
        assertEquals(5, s.runUntilIdle());
        assertEquals(Arrays.asList("a@0.5", "timeout1@1.0", "timeout2@1.0", "heartbeat@1.0", "b@2.0"), log);
    }

    @Test
    void sameTimeTasksKeepTheirSequenceRegardlessOfHowManyThereAre() {
        Scheduler s = lockstep();
        for (int i = 0; i < 200; i++) {
            s.schedule(3.0, Scheduler.NORMAL, record("t" + i));
        }
        s.runUntilIdle();
        for (int i = 0; i < 200; i++) {
            assertEquals("t" + i + "@3.0", log.get(i));
        }
    }

    @Test
    void immediateTasksRunBeforeTimedOnesAtTheCurrentTime() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, t -> {
            log.add("first@" + t);
            s.scheduleImmediate(record("immediate"));
            s.schedule(1.0, Scheduler.NORMAL, record("sameTime"));
        });
        s.schedule(1.0, Scheduler.NORMAL, record("second"));
        s.runUntilIdle();
        assertEquals(Arrays.asList("first@1.0", "immediate@1.0", "second@1.0", "sameTime@1.0"), log);
    }

    @Test
    void aQueuedTaskIsNotQueuedTwice() {
        Scheduler s = lockstep();
        Task motion = record("motion");
        assertTrue(s.schedule(1.0, Scheduler.NORMAL, motion));
        assertFalse(s.schedule(0.5, Scheduler.NORMAL, motion), "already queued: the earlier entry stays");
        assertEquals(1, s.size());
        s.runUntilIdle();
        assertEquals(Arrays.asList("motion@1.0"), log);
        assertTrue(s.schedule(2.0, Scheduler.NORMAL, motion), "once run it can be queued again");
    }

    @Test
    void cancelledTasksDoNotRun() {
        Scheduler s = lockstep();
        Task heartbeat = record("beat");
        s.schedule(1.0, Scheduler.HEARTBEAT, heartbeat);
        s.schedule(2.0, Scheduler.NORMAL, record("other"));
        assertTrue(s.cancel(heartbeat));
        assertFalse(s.cancel(heartbeat));
        s.runUntilIdle();
        assertEquals(Arrays.asList("other@2.0"), log);
    }

    @Test
    void lockstepTimeJumpsFromTaskToTask() {
        Scheduler s = lockstep();
        s.schedule(1000.0, Scheduler.NORMAL, record("late"));
        assertEquals(0.0, s.now());
        s.runNext();
        assertEquals(1000.0, s.now());
        assertEquals(Arrays.asList("late@1000.0"), log);
    }

    @Test
    void aTaskQueuedInThePastRunsAtOnceStampedWithItsOwnTimeWithoutPullingTheClockBack() {
        Scheduler s = lockstep();
        s.schedule(5.0, Scheduler.NORMAL, t -> s.schedule(3.0, Scheduler.NORMAL, record("negativeTimeout")));
        s.schedule(6.0, Scheduler.NORMAL, record("next"));
        s.runUntilIdle();
        assertEquals(Arrays.asList("negativeTimeout@3.0", "next@6.0"), log);
    }

    @Test
    void nothingRunsWhileTheClockIsStopped() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        s.scheduleImmediate(record("immediate"));
        s.stopClock();
        assertFalse(s.runNext());
        s.startClock();
        assertEquals(2, s.runUntilIdle());
    }

    @Test
    void aPacedClockRunsATaskOnlyWhenWallTimeTimesSpeedReachesIt() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 20.0));
        s.startClock();
        s.schedule(1.0, Scheduler.NORMAL, record("a"));
        wallNanos[0] = 40_000_000L;
        assertFalse(s.runNext(), "0.04 s of wall time at speed 20 is 0.8 s of simulation time");
        assertEquals(0.8, s.now(), 1e-12);
        wallNanos[0] = 60_000_000L;
        s.schedule(1.1, Scheduler.NORMAL, record("b"));
        assertTrue(s.runNext());
        assertEquals(Arrays.asList("a@1.0"), log);
        assertEquals(1.1, s.now(), 1e-12, "1.2 s by the wall clock, but time never runs past a waiting task");
        s.runNext();
        assertEquals(1.2, s.now(), 1e-12, "with nothing queued it follows the wall clock");
    }

    @Test
    void aStoppedPacedClockFreezesAndResumesFromWhereItStopped() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.startClock();
        wallNanos[0] = 500_000_000L;
        s.stopClock();
        wallNanos[0] = 10_000_000_000L;
        assertEquals(0.5, s.now(), 1e-12, "ten seconds of handler time cost no simulation time");
        s.startClock();
        wallNanos[0] = 10_250_000_000L;
        assertEquals(0.75, s.now(), 1e-12);
    }
}
