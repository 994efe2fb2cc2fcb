package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Velocities and durations of any finite size pass the wire (docs/protocol.md section 14); a motion
 * is cut at a billion metres of travel or a billion radians of turn (docs/behavior.md section 5.2), so
 * that the robot still stops at the walls of its room and keeps a pose of numbers.
 */
@Timeout(60)
class AbsurdMotionsTest {
    @TempDir
    Path dir;

    @Test
    void aRobotAskedForAbsurdMotionsStaysInItsRoomWithAPoseOfNumbers() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=max", "interlockEnabled=true");
        try {
            TcpRobot robot = TcpRobot.connect(server.getPort(), "absurd").startLoop();
            robot.sendPlacementRequest(TestServer.placementName(1));
            robot.await(RsPlacementEvent.class, e -> e.valid);

            // 2 m/s for 1e308 s: its wall search overflowed and the robot drove through the room's wall.
            RsMotionHaltedEvent far = drive(robot, new RsMotionRequest(2.0, 0.0, 1e308), 1);
            assertEquals(RsMotionHaltedEvent.HALTED_ON_COLLISION, far.causeOfHalt, "it stops at the east wall");
            assertTrue(far.x > 19.0 && far.x < 20.0, "inside the room: x = " + far.x);

            // Back into the room, then the fastest turn there is: its pose became NaN.
            drive(robot, new RsMotionRequest(-1.0, 0.0, 2.0), 2);
            RsMotionHaltedEvent spun = drive(robot, new RsMotionRequest(0.0, 1e308, 10.0), 3);
            assertTrue(Double.isFinite(spun.x) && Double.isFinite(spun.y) && Double.isFinite(spun.orientation),
                    "a pose of numbers: " + spun.x + ", " + spun.y + ", " + spun.orientation);

            // The longest drive there is goes to the wall, like any other.
            RsMotionHaltedEvent longest = drive(robot, new RsMotionRequest(1.0, 0.0, Double.MAX_VALUE), 4);
            assertTrue(Double.isFinite(longest.x) && longest.x < 20.0, "x = " + longest.x);
            robot.leave();
        } finally {
            server.stop();
        }
    }

    /** Sends {@code q} and returns the {@code n}th motion-halted event the robot was sent. */
    private static RsMotionHaltedEvent drive(TcpRobot robot, RsMotionRequest q, int n) throws Exception {
        robot.sendMotionRequest(q);
        robot.await(RsMotionHaltedEvent.class, e -> robot.events(RsMotionHaltedEvent.class).size() >= n);
        return robot.events(RsMotionHaltedEvent.class).get(n - 1);
    }
}
