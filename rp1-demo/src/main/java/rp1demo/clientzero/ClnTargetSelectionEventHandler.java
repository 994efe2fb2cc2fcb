package rp1demo.clientzero;

import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSelectionEventHandler;

/** Reports targets being switched on or off (for example by another client). */
public class ClnTargetSelectionEventHandler implements RsTargetSelectionEventHandler {
    private final ClnMain client;

    public ClnTargetSelectionEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsTargetSelectionEvent event) {
        client.log("Target " + event.targetName + (event.status ? " selected" : " deselected"));
    }
}
