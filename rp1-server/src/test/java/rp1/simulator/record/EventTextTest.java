package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;

/** The event log's line format (docs/recording.md): users diff it, so it must not drift. */
class EventTextTest {
    @Test
    void aLineHoldsTheTimeTheClientTheEventsNameAndItsFieldsByTheirApiNames() {
        assertEquals("2.5 1 MotionHalted causeOfHalt=2 x=1.25 y=-0.5 orientation=3.141592653589793 duration=0.1",
                EventText.line(1, new RsMotionHaltedEvent(2.5, 2, 1.25, -0.5, Math.PI, 0.1)));
        assertEquals("0.0 3 Placement valid=false name=\"a \\\"b\\\"\" x=0.0 y=0.0 orientation=0.0",
                EventText.line(3, new RsPlacementEvent(0.0, false, "a \"b\"", 0.0, 0.0, 0.0)));
        assertEquals("1.0E-4 2 Timeout timeoutIndex=7", EventText.line(2, new RsTimeoutEvent(1.0e-4, 7)));
    }

    @Test
    void aSensorThatSeesNothingNamedShowsADashForTheName() {
        assertEquals("0.05 1 RangeSensor sensorID=12 status=false range=0.0 x=0.5 y=0.25 ux=1.0 uy=0.0"
                + " nameOfObjectDetected=-",
                EventText.line(1, new RsRangeSensorEvent(0.05, 12, 0.5, 0.25, 1.0, 0.0, false, 0.0)));
    }
}
