package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The interlock as clients see it: every event stops the clock until it is acknowledged. */
class InterlockTest {
    private final Scheduler scheduler = new Scheduler(SimClock.lockstep());
    private final Interlock interlock = new Interlock(scheduler);

    InterlockTest() {
        scheduler.begin();
    }

    @Test
    void numbersComeFromOneCounterAndOnlyTheNewestAcknowledgementRestartsTheClock() {
        Object client = "c";
        assertEquals(1, interlock.open(client));
        assertFalse(scheduler.isClockRunning());
        assertTrue(interlock.close(client, 1));
        assertTrue(scheduler.isClockRunning());

        assertEquals(2, interlock.open(client));
        assertEquals(3, interlock.open(client));
        assertFalse(interlock.close(client, 2), "an older number is ignored");
        assertFalse(scheduler.isClockRunning());
        assertTrue(interlock.close(client, 3));
        assertTrue(scheduler.isClockRunning());
    }

    @Test
    void theClockWaitsForEveryClientThatWasSentAnEvent() {
        assertEquals(1, interlock.open("a"));
        assertEquals(2, interlock.open("b"));
        assertFalse(interlock.close("b", 2), "client a is still handling its event");
        assertFalse(scheduler.isClockRunning());
        assertTrue(interlock.close("a", 1));
        assertTrue(scheduler.isClockRunning());
    }

    @Test
    void aClientThatLeavesWhileTheClockWaitsForItDepartsBeforeTheClockRunsAgain() {
        List<String> order = new ArrayList<>();
        interlock.open("a");
        assertTrue(interlock.leave("a", () -> order.add("departure, clock running: " + scheduler.isClockRunning())));
        assertEquals(List.of("departure, clock running: false"), order);
        assertTrue(scheduler.isClockRunning());
        assertFalse(interlock.isOpen());
    }

    @Test
    void aClientThatLeavesOwingNothingDepartsWhenTheClockWouldNextWaitForIt() {
        List<String> order = new ArrayList<>();
        assertFalse(interlock.leave("a", () -> order.add("departure")));
        assertTrue(interlock.sending("b"), "another client's event is written");
        interlock.close("b", 1);
        assertEquals(List.of(), order, "the clock has not waited for a yet");
        assertFalse(interlock.sending("a"), "nothing is written to a client that has left");
        assertEquals(List.of("departure"), order);
        assertTrue(scheduler.isClockRunning(), "nobody will acknowledge it");
        assertFalse(interlock.sending("a"));
        assertEquals(List.of("departure"), order, "a departure is handed over once");
    }

    @Test
    void aClientThatLeavesOwingNothingAndIsSentNothingDepartsWhenNothingElseCanRun() {
        List<String> order = new ArrayList<>();
        scheduler.schedule(1.0, Scheduler.NORMAL, t -> order.add("task at " + t));
        interlock.leave("a", () -> order.add("departure"));
        assertEquals(1, scheduler.runUntilIdle());
        assertEquals(List.of("task at 1.0", "departure"), order);
    }

    @Test
    void anEventNumberedBeforeItIsWrittenKeepsThatNumberOnTheWire() {
        assertTrue(interlock.sending("x"));
        assertFalse(scheduler.isClockRunning());
        assertEquals(1, interlock.forClient("x", () -> { }).openInterlock());
        assertEquals(1, interlock.getCounter());
        assertTrue(interlock.close("x", 1));
    }

    @Test
    void theConnectionViewReportsTheCounter() {
        assertEquals(1, interlock.forClient("x", () -> { }).openInterlock());
        assertEquals(1, interlock.forClient("y", () -> { }).getMaximumInterlockIndex());
        assertTrue(interlock.forClient("x", () -> { }).closeInterlock(1));
    }
}
