package rp1demo.navigation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

import rp1demo.navigation.NavNetwork.Node;

/**
 * Drives a robot that can turn on the spot along the shortest route of a navigation network: at each
 * node it turns to face the next one, then drives straight to it. Every leg is worked out afresh
 * from where the robot really is, so small errors do not add up.
 */
public final class Autopilot {
    /** A robot within this distance of a node (metres) has reached it. */
    public static final double ARRIVED = 0.01;
    /** Headings closer than this to the next node (radians, 0.1 degree) need no turn. */
    public static final double ON_COURSE = Math.toRadians(0.1);

    private final NavNetwork network;
    private final Consumer<String> report;
    private final Deque<Node> ahead = new ArrayDeque<>();
    private final List<Node> reached = new ArrayList<>();

    /**
     * @param network the roads
     * @param report  where to tell what the autopilot does, one line at a time
     */
    public Autopilot(NavNetwork network, Consumer<String> report) {
        this.network = network;
        this.report = report;
    }

    public NavNetwork getNetwork() {
        return network;
    }

    /**
     * Plans the shortest route from the node nearest to the robot to {@code destination}, replacing
     * any route under way; the robot first drives to that nearest node unless it stands on it.
     *
     * @return the route (empty if the destination cannot be reached)
     */
    public List<Node> routeTo(Pose pose, String destination) {
        ahead.clear();
        Node start = network.nearest(pose.x(), pose.y());
        if (start == null) {
            return Collections.emptyList();
        }
        List<Node> route = network.shortestPath(start.name(), destination).orElse(Collections.emptyList());
        ahead.addAll(route);
        if (!ahead.isEmpty() && pose.distanceTo(start.x(), start.y()) <= ARRIVED) {
            ahead.removeFirst();
        }
        if (!route.isEmpty()) {
            report.accept(String.format(Locale.ROOT, "Route to %s: %s (%.2f m)", destination,
                    NavNetwork.describe(route), NavNetwork.length(route)));
        }
        return route;
    }

    /** Whether part of the route is still ahead. */
    public boolean isTravelling() {
        return !ahead.isEmpty();
    }

    /**
     * The next move from {@code pose}, or null once the robot stands on the route's last node.
     * Nodes the robot has reached are passed (and reported) first.
     */
    public Move next(Pose pose) {
        while (!ahead.isEmpty() && pose.distanceTo(ahead.peekFirst().x(), ahead.peekFirst().y()) <= ARRIVED) {
            Node n = ahead.removeFirst();
            reached.add(n);
            report.accept("Reached node " + n.name());
        }
        Node target = ahead.peekFirst();
        if (target == null) {
            return null;
        }
        double turn = pose.turnTowards(target.x(), target.y());
        if (Math.abs(turn) > ON_COURSE) {
            return new Move.Turn(turn);
        }
        return new Move.Forward(pose.distanceTo(target.x(), target.y()));
    }

    /** Every node reached so far, in order (a node is listed each time it is reached). */
    public List<Node> reachedNodes() {
        return Collections.unmodifiableList(new ArrayList<>(reached));
    }
}
