package rp1demo.adapter;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsPlan;
import rp1demo.navigation.NavNetwork;

/** Builds a {@link NavNetwork} from the nodes and links of a floor plan received in a plan event. */
public final class NavPlans {
    private NavPlans() {
    }

    /** The plan's navigation network (empty if the plan has none). */
    public static NavNetwork network(RsPlan plan) {
        NavNetwork net = new NavNetwork();
        for (RsNavNode n : plan.getNavNodeArray()) {
            net.addNode(n.getName(), n.x, n.y);
        }
        for (RsNavLink l : plan.getNavLinkArray()) {
            net.addLink(l.n0.getName(), l.n1.getName());
        }
        return net;
    }
}
