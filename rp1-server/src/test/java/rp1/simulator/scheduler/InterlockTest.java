package rp1.simulator.scheduler;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
    void aClientThatLeavesReleasesItsInterlock() {
        interlock.open("a");
        interlock.release("a");
        assertTrue(scheduler.isClockRunning());
        assertFalse(interlock.isOpen());
    }

    @Test
    void theConnectionViewReportsTheCounter() {
        assertEquals(1, interlock.forClient("x", () -> { }).openInterlock());
        assertEquals(1, interlock.forClient("y", () -> { }).getMaximumInterlockIndex());
        assertTrue(interlock.forClient("x", () -> { }).closeInterlock(1));
    }
}
