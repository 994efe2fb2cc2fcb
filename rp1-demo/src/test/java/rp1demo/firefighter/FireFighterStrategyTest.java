package rp1demo.firefighter;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1demo.navigation.Move;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.Pose;

/**
 * The search strategy against a pretend robot that carries out every move exactly: a hall with
 * home at its east end and two rooms, A (nearer) and B.
 */
class FireFighterStrategyTest {

    /** Carries out moves exactly and remembers what it was told. */
    private static final class PretendRobot implements FireFighter.Robot {
        Move pending;
        int stops;
        Boolean success;
        final List<Move> moves = new ArrayList<>();

        @Override
        public void drive(Move move) {
            pending = move;
            moves.add(move);
        }

        @Override
        public void stop() {
            stops++;
        }

        @Override
        public void finished(boolean ok) {
            success = ok;
        }
    }

    private static NavNetwork house() {
        NavNetwork n = new NavNetwork();
        n.addNode("home", 4, 0);
        n.addNode("hall", 0, 0);
        n.addNode("roomA", 0, 1);
        n.addNode("roomB", 0, -2);
        n.addLink("home", "hall");
        n.addLink("hall", "roomA");
        n.addLink("hall", "roomB");
        return n;
    }

    private static Pose apply(Pose p, Move m) {
        if (m instanceof Move.Turn t) {
            return new Pose(p.x(), p.y(), Pose.normalize(p.heading() + t.angle()));
        }
        double d = ((Move.Forward) m).distance();
        return new Pose(p.x() + d * Math.cos(p.heading()), p.y() + d * Math.sin(p.heading()), p.heading());
    }

    /** Completes moves until the strategy finishes or a full-circle look-around starts at (x, y). */
    private static Pose runUntilScanAt(FireFighter ff, PretendRobot robot, Pose pose, double x, double y) {
        for (int i = 0; i < 50 && robot.success == null; i++) {
            Move m = robot.pending;
            if (m instanceof Move.Turn t && Math.abs(t.angle()) > 6.0 && pose.distanceTo(x, y) < 1e-9) {
                return pose;
            }
            pose = apply(pose, m);
            ff.moveEnded(pose);
        }
        return pose;
    }

    @Test
    void withNoCandleItLooksRoundEveryRoomNearestFirstAndGoesHome() {
        PretendRobot robot = new PretendRobot();
        List<String> said = new ArrayList<>();
        FireFighter ff = new FireFighter(house(), 0.4, 1.2, robot, said::add);
        Pose pose = new Pose(4, 0, Math.PI);
        ff.start(pose);
        runUntilScanAt(ff, robot, pose, 99, 99);

        assertEquals(Boolean.FALSE, robot.success);
        assertTrue(ff.isDone());
        assertNull(ff.getCandle());
        long scans = robot.moves.stream().filter(m -> m instanceof Move.Turn t && t.angle() == 2 * Math.PI).count();
        assertEquals(2, scans, "one look round per room");
        assertTrue(said.indexOf("Going to room roomA") < said.indexOf("Going to room roomB"), said.toString());
    }

    @Test
    void aCandleSightedWhileLookingRoundStopsItAndItDrivesUpToTheCandle() {
        PretendRobot robot = new PretendRobot();
        FireFighter ff = new FireFighter(house(), 0.4, 1.2, robot, s -> { });
        Pose pose = new Pose(4, 0, Math.PI);
        ff.start(pose);
        pose = runUntilScanAt(ff, robot, pose, 0, 1);
        ff.candleOutOfSight();
        pose = apply(pose, robot.pending);
        ff.moveEnded(pose);
        pose = runUntilScanAt(ff, robot, pose, 0, -2);

        ff.candleInSight("far", 3.0, -2.0);
        assertEquals(0, robot.stops, "a candle beyond reach is in another room");
        ff.candleInSight("C", 0.5, -2.8);
        assertEquals(1, robot.stops);
        Pose stopped = new Pose(0, -2, 1.0);
        ff.moveEnded(stopped);
        pose = stopped;
        for (int i = 0; i < 5 && robot.success == null; i++) {
            pose = apply(pose, robot.pending);
            ff.moveEnded(pose);
        }
        assertEquals(Boolean.TRUE, robot.success);
        assertEquals("C", ff.getCandle().name());
        assertEquals(0.4, pose.distanceTo(0.5, -2.8), 1e-9);
        assertEquals(0.0, pose.turnTowards(0.5, -2.8), 1e-9);
    }

    @Test
    void aCandleInViewOnArrivalIsApproachedWithoutLookingRound() {
        PretendRobot robot = new PretendRobot();
        FireFighter ff = new FireFighter(house(), 0.4, 1.2, robot, s -> { });
        Pose pose = new Pose(4, 0, Math.PI);
        ff.start(pose);
        ff.candleInSight("C", 0.0, 1.8);
        for (int i = 0; i < 20 && robot.success == null; i++) {
            pose = apply(pose, robot.pending);
            ff.moveEnded(pose);
        }
        assertEquals(Boolean.TRUE, robot.success);
        assertFalse(robot.moves.stream().anyMatch(m -> m instanceof Move.Turn t && t.angle() == 2 * Math.PI));
        assertEquals(0.4, pose.distanceTo(0.0, 1.8), 1e-9);
    }
}
