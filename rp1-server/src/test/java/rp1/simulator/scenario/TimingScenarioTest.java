package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.simulator.SimulationSettings;

/** Timeouts, heartbeats and their order at equal times (behavior.md sections 4.1 and 4.3). */
@Timeout(60)
class TimingScenarioTest {

    private static List<String> timing(ScenarioClient c) {
        List<String> out = new ArrayList<>();
        for (RsEvent e : c.events()) {
            if (e instanceof RsTimeoutEvent) {
                out.add("timeout" + ((RsTimeoutEvent) e).timeoutIndex + "@" + e.simTime);
            } else if (e instanceof RsHeartbeatEvent) {
                out.add("beat" + ((RsHeartbeatEvent) e).sequence + "@" + e.simTime);
            }
        }
        return out;
    }

    @Test
    void atEqualTimesTimeoutsComeInRequestOrderAndHeartbeatsLast() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.on(RsHeartbeatEvent.class, b -> {
                if (b.sequence == 3) {
                    c.sendHeartbeatCancellationRequest();
                }
            });
            c.sendHeartbeatRequest(0.5);
            c.sendTimeoutRequest(1.0);
            c.sendTimeoutRequest(0.5);
            c.sendTimeoutRequest(1.0);
            c.await(RsHeartbeatEvent.class, b -> b.sequence == 3);
            c.sendTimeoutRequest(10.0);
            c.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 4);
            assertEquals(Arrays.asList("timeout2@0.5", "beat1@0.5", "timeout1@1.0", "timeout3@1.0", "beat2@1.0", "beat3@1.5",
                    "timeout4@11.5"), timing(c), "no beat after the cancellation sent at the third");
        }
    }

    @Test
    void heartbeatsDoNotDriftAndRestartTheirCountOnANewRequest() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.on(RsHeartbeatEvent.class, b -> {
                if (b.sequence == 30 && b.simTime < 3.1) {
                    c.sendHeartbeatRequest(0.25);
                } else if (b.simTime > 3.1) {
                    c.sendHeartbeatCancellationRequest();
                }
            });
            c.sendHeartbeatRequest(0.1);
            RsHeartbeatEvent thirtieth = c.await(RsHeartbeatEvent.class, b -> b.sequence == 30);
            assertEquals(3.0, thirtieth.simTime, 0.0, "beat k at exactly k * 0.1, not a sum of 30 steps");
            RsHeartbeatEvent restarted = c.await(RsHeartbeatEvent.class, b -> b.simTime > 3.1);
            assertEquals(1, restarted.sequence, "a new request restarts the count");
            assertEquals(3.25, restarted.simTime, 1e-12);
        }
    }

    @Test
    void aHeartbeatFasterThanAMillisecondIsSlowedToOneAndTimeRunsOnForEveryone() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient fast = s.connect(new ScenarioClient(Bodies.round("fast")));
            ScenarioClient other = s.connect(new ScenarioClient(Bodies.round("other")));
            fast.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            fast.on(RsHeartbeatEvent.class, b -> {
                if (b.sequence == 20) {
                    fast.sendHeartbeatCancellationRequest();
                }
            });
            fast.sendHeartbeatRequest(1e-300);
            other.sendTimeoutRequest(0.01);
            RsHeartbeatEvent fifth = fast.await(RsHeartbeatEvent.class, b -> b.sequence == 5);
            assertEquals(0.005, fifth.simTime, 1e-12, "beats every millisecond, the floor");
            assertEquals(0.01, other.await(RsTimeoutEvent.class).simTime, 1e-12, "the other client's time came");
        }
    }

    @Test
    void aZeroLengthTimeoutReadsTheClock() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.once(RsTimeoutEvent.class, e -> c.sendTimeoutRequest(0.0));
            c.sendTimeoutRequest(2.5);
            RsTimeoutEvent second = c.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 2);
            assertEquals(2.5, second.simTime, "fires at the time it was requested");
        }
    }

    @Test
    void aNegativeTimeoutFiresAtOnceStampedInThePast() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.once(RsTimeoutEvent.class, e -> c.sendTimeoutRequest(-1.0));
            c.sendTimeoutRequest(2.0);
            RsTimeoutEvent past = c.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 2);
            assertEquals(1.0, past.simTime);
        }
    }

    @Test
    void aNegativeTimeoutDoesNotTurnALockstepClockBack() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            assertTheClockNeverGoesBack(s);
        }
    }

    @Test
    void aNegativeTimeoutDoesNotTurnAPacedClockBack() throws Exception {
        try (Scenario s = Scenario.with(Plans.HALL, SimulationSettings.paced(0.05, 1.0, true, 1L))) {
            assertTheClockNeverGoesBack(s);
        }
    }

    /**
     * Issue 18.2: a timeout of +0.5 s, then -2 s asked for in answer to it, then +0.2 s in answer to
     * that. The past-due event keeps RP1 0.60's stamp, its due time in the past; everything after it is
     * stamped at or after every time already sent, the +0.2 s timeout 0.2 s after the first. A second
     * timeout due at 0.5 s holds a paced clock at 0.5 while the client answers, so the stamps are exact
     * at any speed (and the same with every delivery, DeliveryEquivalenceTest).
     */
    private static void assertTheClockNeverGoesBack(Scenario s) throws InterruptedException {
        ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
        c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
        c.on(RsTimeoutEvent.class, e -> {
            if (e.timeoutIndex == 1) {
                c.sendTimeoutRequest(-2.0);
            } else if (e.timeoutIndex == 3) {
                c.sendTimeoutRequest(0.2);
            }
        });
        c.sendTimeoutRequest(0.5);
        c.sendTimeoutRequest(0.5);
        RsTimeoutEvent last = c.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 4);
        RsTimeoutEvent past = c.await(RsTimeoutEvent.class, e -> e.timeoutIndex == 3);
        assertEquals(-1.5, past.simTime, 1e-12, "the past-due event carries its due time");
        assertEquals(0.7, last.simTime, 1e-12, "+0.2 s counts from where the clock stood");
        double latest = Double.NEGATIVE_INFINITY;
        for (RsEvent e : c.events()) {
            if (e != past) {
                assertTrue(e.simTime >= latest, "time went back to " + e.simTime + " after " + latest + ":\n"
                        + c.transcript());
                latest = Math.max(latest, e.simTime);
            }
        }
    }

    @Test
    void thePlanEventIsStampedZeroAndResetsTheClientsClock() throws Exception {
        try (Scenario s = Scenario.lockstep(Plans.HALL)) {
            ScenarioClient c = s.connect(new ScenarioClient(Bodies.round("bot")));
            c.sendPlacementRequest("west"); // at max speed, time passes only while a robot is on the floor
            c.once(RsTimeoutEvent.class, e -> c.sendPlanRequest());
            c.sendTimeoutRequest(4.0);
            RsPlanEvent plan = c.await(RsPlanEvent.class);
            assertEquals(0.0, plan.simTime);
            assertEquals("hall", ((rp1.rossum.RsPlan) plan.plan).getCaption());
        }
    }
}
