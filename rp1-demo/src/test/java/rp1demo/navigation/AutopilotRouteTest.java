package rp1demo.navigation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The autopilot driving an L-shaped route, each move carried out exactly. */
class AutopilotRouteTest {

    private static Pose apply(Pose p, Move m) {
        if (m instanceof Move.Turn t) {
            return new Pose(p.x(), p.y(), Pose.normalize(p.heading() + t.angle()));
        }
        double d = ((Move.Forward) m).distance();
        return new Pose(p.x() + d * Math.cos(p.heading()), p.y() + d * Math.sin(p.heading()), p.heading());
    }

    @Test
    void itTurnsToFaceEachNodeThenDrivesStraightToItAndReportsTheNodesReached() {
        NavNetwork n = new NavNetwork();
        n.addNode("start", 0, 0);
        n.addNode("corner", 2, 0);
        n.addNode("end", 2, 1);
        n.addLink("start", "corner");
        n.addLink("corner", "end");
        List<String> said = new ArrayList<>();
        Autopilot pilot = new Autopilot(n, said::add);
        Pose pose = new Pose(0, 0, Math.PI / 2);
        assertEquals(3, pilot.routeTo(pose, "end").size());

        List<Move> moves = new ArrayList<>();
        for (Move m = pilot.next(pose); m != null; m = pilot.next(pose)) {
            moves.add(m);
            pose = apply(pose, m);
            assertTrue(moves.size() < 10, "the route ends");
        }
        assertEquals(4, moves.size(), moves.toString());
        assertEquals(-Math.PI / 2, ((Move.Turn) moves.get(0)).angle(), 1e-12);
        assertEquals(2.0, ((Move.Forward) moves.get(1)).distance(), 1e-12);
        assertEquals(Math.PI / 2, ((Move.Turn) moves.get(2)).angle(), 1e-12);
        assertInstanceOf(Move.Forward.class, moves.get(3));
        assertEquals(2.0, pose.x(), 1e-9);
        assertEquals(1.0, pose.y(), 1e-9);
        assertEquals(List.of("corner", "end"), pilot.reachedNodes().stream().map(NavNetwork.Node::name).toList());
        assertFalse(pilot.isTravelling());
        assertTrue(said.contains("Reached node end"), said.toString());
        assertNull(pilot.next(pose));
    }
}
