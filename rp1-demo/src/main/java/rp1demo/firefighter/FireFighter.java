package rp1demo.firefighter;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

import rp1demo.navigation.Autopilot;
import rp1demo.navigation.Move;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.NavNetwork.Node;
import rp1demo.navigation.Pose;

/**
 * The fire fighter's search strategy. The rooms are the dead ends of the navigation network; the
 * robot visits them nearest first, each by the shortest route. Standing in a room it looks around
 * once, turning on the spot; when a candle comes into view it stops, turns to face the candle and
 * drives up to it, stopping a safe distance before it. If no room holds a candle it goes home.
 *
 * <p>The strategy knows nothing of the simulator: it is told where the robot is when a move ends,
 * what the candle sensor sees, and it answers through {@link Robot}.
 */
public final class FireFighter {
    /** What the fire fighter asks of its robot. */
    public interface Robot {
        /** Start this move (replacing any under way); report its end through {@link #moveEnded}. */
        void drive(Move move);

        /** Stop now; report the end of the move through {@link #moveEnded}. */
        void stop();

        /** The search is over: {@code success} if the robot stands before a candle. */
        void finished(boolean success);
    }

    /**
     * A candle as the sensor located it.
     *
     * @param name the target's name
     * @param x    metres
     * @param y    metres
     */
    public record Candle(String name, double x, double y) {
    }

    private enum Phase { IDLE, TRAVELLING, SCANNING, STOPPING, APPROACHING, RETURNING, DONE }

    private final NavNetwork network;
    private final Autopilot pilot;
    private final Robot robot;
    private final Consumer<String> report;
    private final double standoff;
    private final double reach;
    private final Deque<String> rooms = new ArrayDeque<>();
    private final Deque<Move> approach = new ArrayDeque<>();
    private Phase phase = Phase.IDLE;
    private String home;
    private Candle inSight;
    /** Where the robot turns on the spot looking for candles. */
    private Pose lookout;
    private volatile Candle found;
    private volatile boolean done;

    /**
     * @param network  the house's navigation network
     * @param standoff how far from the candle the robot's centre stops, metres
     * @param reach    candles farther than this from the robot when it looks around are left alone
     *                 (they are not in the room it stands in), metres
     * @param robot    the robot to command
     * @param report   where to tell what the fire fighter does, one line at a time
     */
    public FireFighter(NavNetwork network, double standoff, double reach, Robot robot, Consumer<String> report) {
        this.network = network;
        this.pilot = new Autopilot(network, report);
        this.standoff = standoff;
        this.reach = reach;
        this.robot = robot;
        this.report = report;
    }

    /** Begins the search from {@code pose}; the node nearest to it is home. */
    public void start(Pose pose) {
        Node start = network.nearest(pose.x(), pose.y());
        if (start == null) {
            report.accept("No navigation network: cannot search");
            finish(false);
            return;
        }
        home = start.name();
        List<Node> candidates = new ArrayList<>(network.deadEnds());
        candidates.remove(start);
        candidates.sort(Comparator.comparingDouble(n -> routeLength(start, n)));
        for (Node n : candidates) {
            rooms.add(n.name());
        }
        report.accept("Searching the rooms " + String.join(", ", rooms) + ", nearest first");
        nextRoom(pose);
    }

    private double routeLength(Node from, Node to) {
        return network.shortestPath(from.name(), to.name()).map(NavNetwork::length).orElse(Double.POSITIVE_INFINITY);
    }

    private void nextRoom(Pose pose) {
        String room = rooms.pollFirst();
        if (room == null) {
            report.accept("No candle in any room; going home");
            phase = Phase.RETURNING;
            pilot.routeTo(pose, home);
        } else {
            report.accept("Going to room " + room);
            phase = Phase.TRAVELLING;
            pilot.routeTo(pose, room);
        }
        travel(pose);
    }

    private void travel(Pose pose) {
        Move m = pilot.next(pose);
        if (m != null) {
            robot.drive(m);
        } else if (phase == Phase.RETURNING) {
            report.accept("Home again, without having found a candle");
            finish(false);
        } else {
            lookAround(pose);
        }
    }

    /** In a room: a candle already in view is approached at once, else the robot turns a full circle. */
    private void lookAround(Pose pose) {
        if (inSight != null && pose.distanceTo(inSight.x(), inSight.y()) <= reach) {
            report.accept("Candle " + inSight.name() + " in view");
            approach(pose, inSight);
            return;
        }
        report.accept("Looking around");
        lookout = pose;
        phase = Phase.SCANNING;
        robot.drive(new Move.Turn(2.0 * Math.PI));
    }

    /** The move under way ended (completed, or stopped on request) with the robot at {@code pose}. */
    public void moveEnded(Pose pose) {
        switch (phase) {
            case TRAVELLING, RETURNING -> travel(pose);
            case SCANNING -> {
                report.accept("No candle here");
                nextRoom(pose);
            }
            case STOPPING -> approach(pose, found);
            case APPROACHING -> approachStep(pose);
            default -> { }
        }
    }

    /** The candle sensor sees candle {@code name} at (x, y). */
    public void candleInSight(String name, double x, double y) {
        inSight = new Candle(name, x, y);
        if (phase == Phase.SCANNING && lookout.distanceTo(x, y) <= reach) {
            found = inSight;
            phase = Phase.STOPPING;
            report.accept(String.format(Locale.ROOT, "Candle %s sighted at (%.3f, %.3f)", name, x, y));
            robot.stop();
        }
    }

    /** The candle sensor sees nothing. */
    public void candleOutOfSight() {
        inSight = null;
    }

    /** The robot ran into something at {@code pose}: the search is abandoned. */
    public void blocked(Pose pose) {
        report.accept("Ran into a wall at " + pose + "; giving up");
        finish(false);
    }

    private void approach(Pose pose, Candle candle) {
        found = candle;
        phase = Phase.APPROACHING;
        approach.clear();
        double turn = pose.turnTowards(candle.x(), candle.y());
        if (Math.abs(turn) > Autopilot.ON_COURSE) {
            approach.add(new Move.Turn(turn));
        }
        double run = pose.distanceTo(candle.x(), candle.y()) - standoff;
        if (run > 0.0) {
            approach.add(new Move.Forward(run));
        }
        approachStep(pose);
    }

    private void approachStep(Pose pose) {
        Move m = approach.pollFirst();
        if (m != null) {
            robot.drive(m);
            return;
        }
        report.accept(String.format(Locale.ROOT, "Standing %.2f m before candle %s at %s",
                pose.distanceTo(found.x(), found.y()), found.name(), pose));
        finish(true);
    }

    private void finish(boolean success) {
        phase = Phase.DONE;
        done = true;
        robot.finished(success);
    }

    /** Whether the search is over. */
    public boolean isDone() {
        return done;
    }

    /** The candle the robot went for, or null. */
    public Candle getCandle() {
        return found;
    }
}
