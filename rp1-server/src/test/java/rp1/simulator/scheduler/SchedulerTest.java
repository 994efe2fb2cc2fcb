package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.DoubleConsumer;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Task order, simulation time, boundaries and the right to run tasks, driven step by step. */
class SchedulerTest {
    private final List<String> log = Collections.synchronizedList(new ArrayList<>());

    private Task record(String name) {
        return t -> log.add(name + "@" + t);
    }

    private static Scheduler lockstep() {
        Scheduler s = new Scheduler(SimClock.lockstep());
        s.begin();
        return s;
    }

    @Test
    void tasksRunByTimeThenPriorityThenInsertionOrder() {
        Scheduler s = lockstep();
        s.schedule(2.0, Scheduler.NORMAL, record("b"));
        s.schedule(1.0, Scheduler.LATE, record("heartbeat"));
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
    void immediateTasksRunBeforeTimedOnesAtTheTimeTheyWereStampedWith() {
        Scheduler s = lockstep();
        s.schedule(1.0, Scheduler.NORMAL, t -> {
            log.add("first@" + t);
            s.scheduleImmediate(t, record("immediate"));
            s.schedule(1.0, Scheduler.NORMAL, record("sameTime"));
        });
        s.schedule(1.0, Scheduler.NORMAL, record("second"));
        s.runUntilIdle();
        assertEquals(Arrays.asList("first@1.0", "immediate@1.0", "second@1.0", "sameTime@1.0"), log);
    }

    @Test
    void aHandleSaysWhetherItsTaskStillWaitsAndCancelsIt() {
        Scheduler s = lockstep();
        TaskHandle beat = s.schedule(1.0, Scheduler.LATE, record("beat"));
        TaskHandle other = s.schedule(2.0, Scheduler.NORMAL, record("other"));
        assertTrue(beat.isScheduled());
        assertEquals(2, s.size());
        assertTrue(beat.cancel());
        assertFalse(beat.cancel(), "cancelled once");
        assertFalse(beat.isScheduled());
        assertEquals(1, s.size());
        s.runUntilIdle();
        assertEquals(Arrays.asList("other@2.0"), log);
        assertFalse(other.isScheduled(), "it ran");
        assertFalse(other.cancel(), "a task that ran cannot be cancelled");
    }

    @Test
    void observersRunAfterEveryModelTaskDueThenAndAreNotCountedAsModelTasks() {
        Scheduler s = lockstep();
        s.observeAt(1.0, record("picture"));
        s.schedule(1.0, Scheduler.LATE, record("heartbeat"));
        s.schedule(1.0, Scheduler.NORMAL, record("step"));
        s.runUntilIdle();
        assertEquals(Arrays.asList("step@1.0", "heartbeat@1.0", "picture@1.0"), log);
        assertEquals(2, s.modelTasksRun());
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
        s.scheduleImmediate(0.0, record("immediate"));
        s.stopClock();
        assertFalse(s.runNext());
        s.resumeClock();
        assertEquals(2, s.runUntilIdle());
    }

    @Test
    void beforeTheRunBeginsInputsAreAppliedAtTimeZeroButNoTaskRuns() {
        Scheduler s = new Scheduler(SimClock.lockstep());
        InputQueue inputs = new InputQueue(s);
        inputs.submit(input(1, false, "placement request"));
        s.scheduleImmediate(0.0, record("immediate"));
        assertFalse(s.runNext());
        assertEquals(Arrays.asList("placement request@0.0"), log);
        s.begin();
        assertTrue(s.runNext());
    }

    @Test
    void aHeldClockRunsWhatIsDueNowButDoesNotAdvance() {
        Scheduler s = lockstep();
        s.hold();
        s.schedule(0.0, Scheduler.NORMAL, record("placement"));
        s.schedule(5.0, Scheduler.NORMAL, record("later"));
        assertEquals(1, s.runUntilIdle());
        assertEquals(0.0, s.now());
        s.release();
        assertEquals(1, s.runUntilIdle());
        assertEquals(Arrays.asList("placement@0.0", "later@5.0"), log);
    }

    @Test
    void aReplayClockIgnoresHoldsSoTheRecordedTaskSequenceRunsThrough() {
        Scheduler s = new Scheduler(SimClock.replay());
        s.begin();
        s.hold();
        s.schedule(5.0, Scheduler.NORMAL, record("later"));
        assertEquals(5.0, s.nextTaskTime());
        assertEquals(1, s.runUntilIdle());
        assertEquals(Arrays.asList("later@5.0"), log);
        assertEquals(Double.POSITIVE_INFINITY, s.nextTaskTime());
    }

    @Test
    void aReplayMovesTheClockOnToARecordedInputsTimeButNeverBack() {
        Scheduler s = new Scheduler(SimClock.replay());
        s.begin();
        s.advanceTo(2.5);
        assertEquals(2.5, s.now());
        s.advanceTo(1.0);
        assertEquals(2.5, s.now());
    }

    @Test
    void theNextTaskTimeIsAnImmediateTasksStampBeforeAnyTimedTask() {
        Scheduler s = lockstep();
        s.schedule(2.0, Scheduler.NORMAL, record("timed"));
        s.scheduleImmediate(0.5, record("immediate"));
        assertEquals(0.5, s.nextTaskTime());
    }

    @Test
    @Timeout(10)
    void afterShutdownAwaitIdleWaitsForTheTaskInProgressToFinish() throws Exception {
        Scheduler s = lockstep();
        CountDownLatch inside = new CountDownLatch(1);
        s.scheduleImmediate(0.0, t -> {
            inside.countDown();
            sleep(200);
            log.add("finished");
        });
        Thread holder = new Thread(s::runUntilIdle);
        holder.start();
        await(inside, Duration.ofSeconds(5), "the holder is running the task");
        s.shutdown();
        assertTrue(s.awaitIdle(5000));
        assertEquals(Arrays.asList("finished"), log, "the task had finished when awaitIdle returned");
        holder.join(5000);
    }

    @Test
    void inputsAreAppliedAtTheNextBoundaryDeparturesFirstThenBySourceInArrivalOrder() {
        Scheduler s = lockstep();
        InputQueue inputs = new InputQueue(s);
        s.schedule(1.0, Scheduler.NORMAL, t -> {
            log.add("task@" + t);
            inputs.submit(input(2, false, "b1"));
            inputs.submit(input(1, false, "a1"));
            inputs.submit(input(2, false, "b2"));
            inputs.submit(input(3, true, "c leaves"));
            inputs.submit(input(0, false, "view"));
        });
        s.schedule(2.0, Scheduler.NORMAL, record("next"));
        s.runUntilIdle();
        assertEquals(Arrays.asList("task@1.0", "c leaves@1.0", "view@1.0", "a1@1.0", "b1@1.0", "b2@1.0", "next@2.0"), log);
    }

    @Test
    void anInputThatThrowsIsReportedAndTheRestOfTheBatchIsStillApplied() {
        Scheduler s = lockstep();
        List<RuntimeException> failures = new ArrayList<>();
        s.setFailureHandler(failures::add);
        InputQueue inputs = new InputQueue(s);
        inputs.submit(input(1, false, t -> {
            throw new IllegalStateException("a request the world could not take");
        }));
        inputs.submit(input(2, false, "client 2's request"));
        inputs.submit(input(3, true, "client 3 leaves"));
        inputs.cross(1.5);
        assertEquals(List.of("client 3 leaves@1.5", "client 2's request@1.5"), log, "departures first, then by source");
        assertEquals(1, failures.size());
        assertEquals("a request the world could not take", failures.get(0).getMessage());
        assertTrue(inputs.isSettled(), "every input counts as applied");
    }

    private Input input(int source, boolean departure, String name) {
        return input(source, departure, t -> log.add(name + "@" + t));
    }

    private static Input input(int source, boolean departure, DoubleConsumer action) {
        return new Input() {
            @Override
            public int source() {
                return source;
            }

            @Override
            public boolean isDeparture() {
                return departure;
            }

            @Override
            public void apply(double simTime) {
                action.accept(simTime);
            }
        };
    }

    @Test
    void inputsWaitWhileTheClockIsStopped() {
        Scheduler s = lockstep();
        InputQueue inputs = new InputQueue(s);
        s.stopClock();
        inputs.submit(input(1, false, "request"));
        s.runUntilIdle();
        assertTrue(log.isEmpty(), "the interlock holds inputs too");
        s.resumeClock();
        s.runUntilIdle();
        assertEquals(Arrays.asList("request@0.0"), log);
    }

    @Test
    void aPacedClockRunsATaskOnlyWhenWallTimeTimesSpeedReachesIt() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 20.0));
        s.begin();
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
    void aStoppedPacedClockFreezesAndThenCatchesUpWithItsDeadlines() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.begin();
        for (int i = 1; i <= 10; i++) {
            s.schedule(0.1 * i, Scheduler.NORMAL, record("step" + i));
        }
        wallNanos[0] = 150_000_000L;
        assertTrue(s.runNext());
        s.stopClock();
        wallNanos[0] = 650_000_000L;
        assertEquals(0.15, s.now(), 1e-12, "frozen while a client handles its event");
        s.resumeClock();
        assertEquals(5, s.runUntilIdle(), "the steps due by 0.65 s run back to back");
        assertEquals(0.65, s.now(), 1e-12);
    }

    @Test
    void inputsThatArrivedWhileTheClockWasStoppedAreStampedWithTheTimeItStoppedAt() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        InputQueue inputs = new InputQueue(s);
        s.begin();
        wallNanos[0] = 200_000_000L;
        s.stopClock();
        inputs.submit(input(1, false, "answer"));
        wallNanos[0] = 700_000_000L;
        s.resumeClock();
        s.runUntilIdle();
        assertEquals(Arrays.asList("answer@0.2"), log, "the half second the client took is not in the stamp");
        assertEquals(0.7, s.now(), 1e-12, "but the clock catches up with it");
    }

    @Test
    void aTaskDueInThePastDoesNotTurnAPacedClockBack() {
        long[] wallNanos = {500_000_000L};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.begin();
        wallNanos[0] += 500_000_000L;
        assertEquals(0.5, s.now(), 1e-12);
        s.schedule(-1.5, Scheduler.NORMAL, record("negativeTimeout"));
        wallNanos[0] += 1_000_000L;
        assertTrue(s.runNext());
        assertEquals(0.501, s.now(), 1e-12, "the clock goes on from where it was");
        s.schedule(0.701, Scheduler.NORMAL, record("next"));
        wallNanos[0] += 200_000_000L;
        s.runUntilIdle();
        assertEquals(Arrays.asList("negativeTimeout@-1.5", "next@0.701"), log);
    }

    @Test
    void aTaskAtNaNIsRefusedAndAPacedClockRunsOn() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.begin();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> s.schedule(Double.NaN, Scheduler.NORMAL, record("nan")));
        assertEquals("task time is not a number", e.getMessage());
        s.schedule(0.3, Scheduler.NORMAL, record("later"));
        wallNanos[0] = 400_000_000L;
        s.runUntilIdle();
        assertEquals(Arrays.asList("later@0.3"), log);
        assertEquals(0.4, s.now(), 1e-12, "time still advances");
    }

    /**
     * Time with nothing to do is not time lost: a paced run whose only queued task is its end (or
     * with nothing queued at all) keeps its speed however long the scheduler sleeps between looks.
     */
    @Test
    void anIdlePacedClockFollowsTheWallClock() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.begin();
        wallNanos[0] = 4_500_000_000L;
        assertEquals(4.5, s.now(), 1e-9, "nothing queued: a client arriving 4.5 s in is stamped 4.5");
        s.schedule(30.0, Scheduler.NORMAL, record("end"));
        wallNanos[0] = 9_500_000_000L;
        assertEquals(9.5, s.now(), 1e-9, "only the end queued");
        wallNanos[0] = 31_000_000_000L;
        s.runUntilIdle();
        assertEquals(Arrays.asList("end@30.0"), log);
        assertEquals(31.0, s.now(), 1e-9);
    }

    @Test
    void aPacedClockLateWithWorkDueCatchesUpAtMostItsLagLimitPastIt() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 1.0));
        s.begin();
        s.schedule(1.0, Scheduler.NORMAL, record("due"));
        wallNanos[0] = 60_000_000_000L;
        s.runUntilIdle();
        assertEquals(Arrays.asList("due@1.0"), log);
        assertEquals(1.0 + SimClock.MAX_LAG_SECONDS, s.now(), 1e-9, "a minute late is not a minute's burst");
    }

    @Test
    void aPacedClockNeverFallsMoreThanItsLagLimitBehind() {
        long[] wallNanos = {0};
        Scheduler s = new Scheduler(SimClock.paced(() -> wallNanos[0], 2.0));
        s.begin();
        s.stopClock();
        wallNanos[0] = 60_000_000_000L;
        s.resumeClock();
        assertEquals(2.0 * SimClock.MAX_LAG_SECONDS, s.now(), 1e-9, "a minute's pause is not followed by a minute's burst");
        wallNanos[0] += 500_000_000L;
        assertEquals(2.0 * SimClock.MAX_LAG_SECONDS + 1.0, s.now(), 1e-9);
    }

    @Test
    @Timeout(10)
    void aThreadThatPumpsRunsDueTasksUnlessAnotherHoldsTheRightToRun() throws Exception {
        Scheduler s = lockstep();
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch leave = new CountDownLatch(1);
        s.scheduleImmediate(0.0, t -> {
            inside.countDown();
            await(leave, Duration.ofSeconds(5), "the test let the busy task end");
        });
        s.schedule(1.0, Scheduler.NORMAL, record("after"));
        Thread holder = new Thread(s::runUntilIdle);
        holder.start();
        await(inside, Duration.ofSeconds(5), "the holder is running the busy task");
        s.pump(TimeUnit.SECONDS.toNanos(1));
        assertTrue(log.isEmpty(), "the holder is busy; a pump must not run tasks beside it");
        leave.countDown();
        holder.join(5000);
        assertEquals(Arrays.asList("after@1.0"), log, "the holder ran the rest itself");
    }

    @Test
    @Timeout(10)
    void theDispatchLoopWakesForInputsFromAnyThread() throws Exception {
        Scheduler s = lockstep();
        InputQueue inputs = new InputQueue(s);
        Thread loop = new Thread(s::runLoop);
        loop.start();
        CountDownLatch applied = new CountDownLatch(1);
        inputs.submit(new Input() {
            @Override
            public int source() {
                return 1;
            }

            @Override
            public void apply(double simTime) {
                applied.countDown();
            }
        });
        await(applied, Duration.ofSeconds(5), "the dispatch loop applied the input");
        s.shutdown();
        loop.join(5000);
        assertFalse(loop.isAlive());
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
