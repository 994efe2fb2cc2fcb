package rp1demo.navigation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import rp1demo.navigation.NavNetwork.Node;

class NavNetworkTest {
    /**
     * a - b - c in a line, with a detour a - d - c that is longer, and e on its own.
     */
    private static NavNetwork network() {
        NavNetwork n = new NavNetwork();
        n.addNode("a", 0, 0);
        n.addNode("b", 1, 0);
        n.addNode("c", 2, 0);
        n.addNode("d", 1, 1);
        n.addNode("e", 5, 5);
        n.addLink("a", "b");
        n.addLink("b", "c");
        n.addLink("a", "d");
        n.addLink("d", "c");
        return n;
    }

    private static List<String> names(List<Node> route) {
        return route.stream().map(Node::name).toList();
    }

    @Test
    void theShortestRouteIsTakenNotTheOneWithFewerOrEarlierLinks() {
        NavNetwork n = network();
        assertEquals(List.of("a", "b", "c"), names(n.shortestPath("a", "c").orElseThrow()));
        n.addLink("a", "c");
        assertEquals(List.of("a", "c"), names(n.shortestPath("a", "c").orElseThrow()));
        assertEquals(2.0, NavNetwork.length(n.shortestPath("a", "c").orElseThrow()), 1e-12);
    }

    @Test
    void unknownOrUnconnectedNodesHaveNoRouteAndANodeIsARouteToItself() {
        NavNetwork n = network();
        assertTrue(n.shortestPath("a", "e").isEmpty());
        assertTrue(n.shortestPath("a", "zz").isEmpty());
        assertEquals(List.of("b"), names(n.shortestPath("b", "b").orElseThrow()));
    }

    @Test
    void deadEndsAndNearestNodes() {
        NavNetwork n = network();
        n.addNode("f", 3, 0);
        n.addLink("c", "f");
        assertEquals(List.of("f"), names(n.deadEnds()));
        assertEquals("d", n.nearest(0.9, 0.8).name());
        assertEquals(6, n.nodeCount());
        assertEquals(5, n.linkCount());
    }

    @Test
    void badNamesAreRefused() {
        NavNetwork n = network();
        assertThrows(IllegalArgumentException.class, () -> n.addNode("a", 9, 9));
        assertThrows(IllegalArgumentException.class, () -> n.addLink("a", "nowhere"));
    }
}
