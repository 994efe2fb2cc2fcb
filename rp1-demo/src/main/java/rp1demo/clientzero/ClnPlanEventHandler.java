package rp1demo.clientzero;

import rp1.rossum.RsPlan;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPlanEventHandler;
import rp1demo.adapter.NavPlans;
import rp1demo.navigation.NavNetwork;

/**
 * Receives the floor plan and builds its navigation network, which a smarter robot would plan its
 * routes on (the autopilot demo does).
 */
public class ClnPlanEventHandler implements RsPlanEventHandler {
    private final ClnMain client;

    public ClnPlanEventHandler(ClnMain client) {
        this.client = client;
    }

    @Override
    public void process(RsPlanEvent event) {
        if (!(event.plan instanceof RsPlan plan)) {
            client.log("The simulator has no floor plan to send");
            return;
        }
        NavNetwork network = NavPlans.network(plan);
        client.setNavNetwork(network);
        client.log("Floor plan \"" + plan.getCaption() + "\": " + plan.getObjectCount() + " objects, navigation network of "
                + network.nodeCount() + " nodes and " + network.linkCount() + " links");
    }
}
