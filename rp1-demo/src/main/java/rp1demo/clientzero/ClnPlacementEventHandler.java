package rp1demo.clientzero;

import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlacementEventHandler;
import rp1demo.adapter.Poses;

/** Reports whether the robot was put on the floor, and where. */
public class ClnPlacementEventHandler implements RsPlacementEventHandler {
    private final ClnMain client;

    public ClnPlacementEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsPlacementEvent event) {
        if (event.valid) {
            client.log("Placed at \"" + event.name + "\" " + Poses.of(event) + "; click to move");
        } else {
            client.log("Placement \"" + event.name + "\" failed: no such placement, or no room there");
        }
    }
}
