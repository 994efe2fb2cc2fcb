package rp1.simulator.batch;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The smallest sweep a test of one robot's behaviour needs: a plan with one wall and the placement
 * {@code home}, and properties that load the robot, headless, interlocked, as fast as it computes,
 * ending when the robot leaves (or after 10 simulated seconds).
 */
final class HomeSweep {
    private HomeSweep() {
    }

    /** Writes {@code home.txt} and {@code NAME.ini} loading {@code robot} into {@code dir}; returns the properties. */
    static Path properties(Path dir, String name, Class<?> robot) throws IOException {
        Files.write(dir.resolve("home.txt"), List.of("wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"));
        return Files.write(dir.resolve(name + ".ini"), List.of("floorPlanFileName=" + dir.resolve("home.txt"),
                "enableGUI=false", "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max",
                "dlcEnabled=true", "dlcName=" + robot.getName(), "exitWhenClientsDone=true", "maxSimulationTime=10"));
    }
}
