package rp1demo.demozero;

import java.util.Locale;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionHaltedEventHandler;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMotionStartedEventHandler;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlacementEventHandler;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsPositionEventHandler;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTargetSensorEventHandler;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.event.RsTimeoutEventHandler;
import rp1demo.adapter.Poses;
import rp1demo.clientzero.ClnMain;

/**
 * DemoZero's extra handlers: each event ClientZero has dealt with is also shown in the window. They
 * run after ClientZero's own handlers and change nothing of what the robot does. The clock is kept
 * by a timeout of DemoZero's own that re-arms itself; the other timeouts are ClientZero's.
 */
final class DemoEventHandlers implements RsMotionStartedEventHandler, RsMotionHaltedEventHandler,
        RsPositionEventHandler, RsPlacementEventHandler, RsTargetSensorEventHandler, RsTimeoutEventHandler {
    private final ClnMain client;
    private final DemoFrame frame;
    private final double clockPeriod;
    private int clockTimeout = -1;

    DemoEventHandlers(ClnMain client, DemoFrame frame, double clockPeriod) {
        this.client = client;
        this.frame = frame;
        this.clockPeriod = clockPeriod;
    }

    /** Asks for the first clock tick. */
    void startClock() {
        clockTimeout = client.sendTimeoutRequest(clockPeriod);
    }

    @Override
    public void process(RsTimeoutEvent event) {
        if (event.timeoutIndex == clockTimeout) {
            frame.showClock(event.simTime);
            clockTimeout = client.sendTimeoutRequest(clockPeriod);
        }
    }

    @Override
    public void process(RsMotionStartedEvent event) {
        frame.showStatus(String.format(Locale.ROOT, "Moving: %.2f m/s, %.1f deg/s for %.1f s",
                event.linearVelocity, Math.toDegrees(event.rotationalVelocity), event.duration));
    }

    @Override
    public void process(RsMotionHaltedEvent event) {
        frame.showStatus("Halted on " + event.whyHalted());
        frame.showPosition(Poses.of(event).toString());
    }

    @Override
    public void process(RsPositionEvent event) {
        frame.showPosition(Poses.of(event).toString());
    }

    @Override
    public void process(RsPlacementEvent event) {
        frame.showStatus(event.valid ? "Placed at \"" + event.name + "\"" : "Placement \"" + event.name + "\" failed");
        if (event.valid) {
            frame.showPosition(Poses.of(event).toString());
        }
    }

    @Override
    public void process(RsTargetSensorEvent event) {
        frame.showHead(event.status
                ? String.format(Locale.ROOT, "%s at %.2f m, %.0f deg", event.getNameOfObjectDetected(), event.range,
                        Math.toDegrees(event.bearing))
                : "nothing in sight");
    }
}
