package mybot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsTransform;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;
import rp1.simulator.world.Robot;

/**
 * MyRobot in the simulator, in this process, headless and as fast as it computes: the project's
 * mybot.ini, with the clock at max speed and a short run.
 */
class MyRobotTest {
    @TempDir
    Path dir;

    @Test
    void drivesOneMetreFromHomeAndStops() throws Exception {
        String properties = Files.readString(Paths.get("mybot.ini"))
                + "\nenableGUI=false\nsimulationSpeed=max\ninterlockEnabled=true\nmaxSimulationTime=10\nlogToSystemOut=false\n";
        Files.writeString(dir.resolve("test.ini"), properties);

        // The view hook is called when the server starts; what it returns is closed when the server
        // stops, before the robot leaves: the moment to see where it ended.
        AtomicReference<RsTransform> end = new AtomicReference<>();
        LaunchOptions options = LaunchOptions.defaults().withView(context -> () -> {
            Robot robot = context.simulation.getWorld().getRobots().get(0);
            end.set(robot.pose());
        });
        RunningServer server = ServerLauncher.start(new String[] {"-p", "test.ini"}, dir, options);
        assertEquals(0, server.awaitExit(), "exit status");

        // Home in the White Room is (2.5, 2.5), facing 225 degrees: one metre on is 0.707 m back on each axis.
        RsTransform pose = end.get();
        assertTrue(pose != null, "the robot was on the floor at the end");
        assertEquals(2.5 - Math.sqrt(0.5), pose.m13, 0.01, "x");
        assertEquals(2.5 - Math.sqrt(0.5), pose.m23, 0.01, "y");
    }
}
