package rp1demo.autopilot;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;

import rp1demo.navigation.Autopilot;
import rp1demo.navigation.Move;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.NavNetwork.Node;
import rp1demo.navigation.Pose;

/**
 * A tour of a navigation network: from the node the robot starts at, to every dead end of the
 * network (in a house, the rooms) in the order they were declared, each by the shortest route, and
 * back to the start. Tell it where the robot is after every move; it answers with the next move.
 */
public final class Tour {
    private final NavNetwork network;
    private final Autopilot pilot;
    private final Consumer<String> report;
    private final Deque<String> destinations = new ArrayDeque<>();
    private final List<String> visited = new ArrayList<>();
    private String current;
    private volatile boolean finished;

    /**
     * @param network the roads to tour
     * @param report  where to tell what the tour does, one line at a time
     */
    public Tour(NavNetwork network, Consumer<String> report) {
        this.network = network;
        this.pilot = new Autopilot(network, report);
        this.report = report;
    }

    /**
     * Plans the tour from the node nearest to {@code pose} and returns the first move (null if
     * there is nothing to visit).
     */
    public Move start(Pose pose) {
        Node home = network.nearest(pose.x(), pose.y());
        if (home == null) {
            report.accept("No navigation network: nowhere to go");
            finished = true;
            return null;
        }
        for (Node n : network.deadEnds()) {
            if (!n.equals(home)) {
                destinations.add(n.name());
            }
        }
        destinations.add(home.name());
        report.accept("Touring " + String.join(", ", destinations));
        return advance(pose);
    }

    /** The robot finished its last move at {@code pose}: the next move, or null when the tour is over. */
    public Move moveDone(Pose pose) {
        return advance(pose);
    }

    private Move advance(Pose pose) {
        while (true) {
            if (current != null) {
                Move m = pilot.next(pose);
                if (m != null) {
                    return m;
                }
                visited.add(current);
                report.accept("Arrived at " + current);
                current = null;
            }
            if (destinations.isEmpty()) {
                finished = true;
                report.accept("Tour complete");
                return null;
            }
            current = destinations.removeFirst();
            if (pilot.routeTo(pose, current).isEmpty()) {
                report.accept("No route to " + current + "; skipped");
                current = null;
            }
        }
    }

    /** Whether the tour is over. */
    public boolean isFinished() {
        return finished;
    }

    /** The destinations reached so far, in order. */
    public List<String> visited() {
        return Collections.unmodifiableList(new ArrayList<>(visited));
    }

    /** Every node the robot has reached so far, in order. */
    public List<Node> reachedNodes() {
        return pilot.reachedNodes();
    }
}
