package rp1.simulator.session;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.SimClock;

/** Beats at exact multiples of their interval, those due together in the order their heartbeats started. */
class HeartbeatsTest {
    private final List<String> log = new ArrayList<>();
    private final Scheduler scheduler = new Scheduler(SimClock.lockstep());
    private final Heartbeats heartbeats = new Heartbeats(scheduler);

    private Heartbeats.Beater beater(String name) {
        return (time, sequence) -> log.add(name + sequence + "@" + time);
    }

    /** Runs the beats due up to {@code time}, and those due at it. */
    private void runUntil(double time) {
        scheduler.schedule(time + 0.01, Scheduler.LATE, t -> scheduler.shutdown());
        scheduler.runUntilIdle();
    }

    @Test
    void beatsDueTogetherGoOutInTheOrderTheirHeartbeatsStarted() {
        scheduler.begin();
        // c's beats join the time a and b share after theirs were filed: the order is still a, b, c.
        heartbeats.start(beater("a"), 0.0, 0.5);
        heartbeats.start(beater("b"), 0.0, 1.0);
        heartbeats.start(beater("c"), 0.5, 0.5);
        runUntil(2.0);
        assertEquals(List.of("a1@0.5", "a2@1.0", "b1@1.0", "c1@1.0", "a3@1.5", "c2@1.5", "a4@2.0", "b2@2.0", "c3@2.0"),
                log);
    }

    @Test
    void aHeartbeatStartedLaterAtAnEarlierOffsetGoesAfterThoseStartedBefore() {
        scheduler.begin();
        heartbeats.start(beater("x"), 0.25, 0.25);
        heartbeats.start(beater("y"), 0.0, 0.5);
        runUntil(1.0);
        assertEquals(List.of("x1@0.5", "y1@0.5", "x2@0.75", "x3@1.0", "y2@1.0"), log);
    }

    @Test
    void aStoppedHeartbeatSendsNoMoreBeatsNotEvenOneDueAtThatMoment() {
        scheduler.begin();
        List<Heartbeats.Beat> beats = new ArrayList<>();
        heartbeats.start((time, sequence) -> {
            log.add("first" + sequence + "@" + time);
            if (sequence == 2) {
                beats.get(0).stop();
            }
        }, 0.0, 1.0);
        beats.add(heartbeats.start(beater("second"), 0.0, 1.0));
        heartbeats.start(beater("third"), 0.0, 2.0);
        runUntil(4.0);
        assertEquals(List.of("first1@1.0", "second1@1.0", "first2@2.0", "third1@2.0", "first3@3.0", "first4@4.0",
                "third2@4.0"), log);
    }

    @Test
    void withEveryHeartbeatStoppedNothingIsQueued() {
        scheduler.begin();
        Heartbeats.Beat a = heartbeats.start(beater("a"), 0.0, 0.1);
        Heartbeats.Beat b = heartbeats.start(beater("b"), 0.0, 0.3);
        a.stop();
        b.stop();
        assertEquals(0, scheduler.size());
    }
}
