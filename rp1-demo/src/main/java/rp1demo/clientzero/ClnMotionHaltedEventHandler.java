package rp1demo.clientzero;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionHaltedEventHandler;
import rp1demo.adapter.Poses;

/**
 * Reports where and why the robot stopped. After a collision the robot waits a moment and then
 * backs away from the wall, so that it can turn freely when the user clicks again.
 */
public class ClnMotionHaltedEventHandler implements RsMotionHaltedEventHandler {
    private final ClnMain client;

    public ClnMotionHaltedEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsMotionHaltedEvent event) {
        client.log("Motion halted on " + event.whyHalted() + " at " + Poses.of(event));
        if (event.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            client.scheduleBackOff();
        }
    }
}
