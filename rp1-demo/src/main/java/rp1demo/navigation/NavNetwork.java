package rp1demo.navigation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.PriorityQueue;

/**
 * A navigation network: named points joined by straight two-way links a robot can drive along
 * (the "nodes" and "links" of an RP1 floor plan). Finds shortest routes between nodes.
 */
public final class NavNetwork {
    /**
     * A point of the network.
     *
     * @param name unique name
     * @param x    metres
     * @param y    metres
     */
    public record Node(String name, double x, double y) {

        /** Straight-line distance to {@code other}, metres. */
        public double distanceTo(Node other) {
            return Math.hypot(other.x - x, other.y - y);
        }
    }

    private final Map<String, Node> nodes = new LinkedHashMap<>();
    private final Map<String, List<Node>> neighbours = new HashMap<>();
    private int links;

    /**
     * Adds a node.
     *
     * @throws IllegalArgumentException if the name is taken
     */
    public void addNode(String name, double x, double y) {
        if (nodes.containsKey(name)) {
            throw new IllegalArgumentException("duplicate node name: " + name);
        }
        nodes.put(name, new Node(name, x, y));
        neighbours.put(name, new ArrayList<>());
    }

    /**
     * Joins two nodes both ways.
     *
     * @throws IllegalArgumentException if either node is unknown
     */
    public void addLink(String a, String b) {
        Node na = require(a);
        Node nb = require(b);
        neighbours.get(a).add(nb);
        neighbours.get(b).add(na);
        links++;
    }

    private Node require(String name) {
        Node n = nodes.get(name);
        if (n == null) {
            throw new IllegalArgumentException("no node named " + name);
        }
        return n;
    }

    /** The node with this name, or null. */
    public Node node(String name) {
        return nodes.get(name);
    }

    /** All nodes in the order they were added. */
    public List<Node> nodes() {
        return Collections.unmodifiableList(new ArrayList<>(nodes.values()));
    }

    public int nodeCount() {
        return nodes.size();
    }

    public int linkCount() {
        return links;
    }

    /** The nodes with exactly one link, in the order they were added: in a house, the rooms. */
    public List<Node> deadEnds() {
        List<Node> out = new ArrayList<>();
        for (Node n : nodes.values()) {
            if (neighbours.get(n.name()).size() == 1) {
                out.add(n);
            }
        }
        return out;
    }

    /** The node closest to (x, y) (the first added on a tie), or null if there are none. */
    public Node nearest(double x, double y) {
        Node best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (Node n : nodes.values()) {
            double d = Math.hypot(n.x() - x, n.y() - y);
            if (d < bestDistance) {
                best = n;
                bestDistance = d;
            }
        }
        return best;
    }

    /**
     * The shortest route along links from one node to another (Dijkstra), both ends included; of
     * equally short routes, the one found first. Empty if either node is unknown or they are not
     * connected.
     */
    public Optional<List<Node>> shortestPath(String from, String to) {
        if (!nodes.containsKey(from) || !nodes.containsKey(to)) {
            return Optional.empty();
        }
        Map<String, Double> distance = new HashMap<>();
        Map<String, Node> previous = new HashMap<>();
        PriorityQueue<Visit> open = new PriorityQueue<>();
        long order = 0;
        distance.put(from, 0.0);
        open.add(new Visit(nodes.get(from), 0.0, order++));
        while (!open.isEmpty()) {
            Visit v = open.poll();
            if (v.distance > distance.get(v.node.name())) {
                continue;
            }
            if (v.node.name().equals(to)) {
                return Optional.of(walkBack(previous, v.node));
            }
            for (Node next : neighbours.get(v.node.name())) {
                double d = v.distance + v.node.distanceTo(next);
                if (d < distance.getOrDefault(next.name(), Double.POSITIVE_INFINITY)) {
                    distance.put(next.name(), d);
                    previous.put(next.name(), v.node);
                    open.add(new Visit(next, d, order++));
                }
            }
        }
        return Optional.empty();
    }

    private static List<Node> walkBack(Map<String, Node> previous, Node end) {
        Deque<Node> path = new ArrayDeque<>();
        for (Node n = end; n != null; n = previous.get(n.name())) {
            path.addFirst(n);
        }
        return new ArrayList<>(path);
    }

    /** Length of a route, metres. */
    public static double length(List<Node> route) {
        double total = 0.0;
        for (int i = 1; i < route.size(); i++) {
            total += route.get(i - 1).distanceTo(route.get(i));
        }
        return total;
    }

    /** Names of the route's nodes joined by arrows, for the log. */
    public static String describe(List<Node> route) {
        StringBuilder b = new StringBuilder();
        for (Node n : route) {
            if (b.length() > 0) {
                b.append(" -> ");
            }
            b.append(n.name());
        }
        return b.toString();
    }

    /** A node reached at some distance, queued in order of distance, then of discovery. */
    private record Visit(Node node, double distance, long order) implements Comparable<Visit> {
        @Override
        public int compareTo(Visit o) {
            int c = Double.compare(distance, o.distance);
            return c != 0 ? c : Long.compare(order, o.order);
        }
    }
}
