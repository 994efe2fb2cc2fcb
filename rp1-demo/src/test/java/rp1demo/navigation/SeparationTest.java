package rp1demo.navigation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * The demos' robot logic does not depend on the simulator (docs/guide.md section 2): these
 * sources import nothing from {@code rp1.*}, so they could be moved to a real robot as they are.
 */
class SeparationTest {
    private static final Path SOURCES = Paths.get(System.getProperty("rp1.root", ".."))
            .resolve("rp1-demo/src/main/java/rp1demo");
    private static final List<String> ROBOT_LOGIC = List.of(
            "navigation/Pose.java", "navigation/Move.java", "navigation/NavNetwork.java", "navigation/Autopilot.java",
            "clientzero/ClnNavigator.java", "autopilot/Tour.java", "firefighter/FireFighter.java",
            "linetracker/LineFollower.java", "ackerman/CourseDriver.java");

    @Test
    void theRobotLogicImportsNothingFromTheSimulator() throws IOException {
        List<String> offending = new ArrayList<>();
        for (String file : ROBOT_LOGIC) {
            for (String line : Files.readAllLines(SOURCES.resolve(file))) {
                if (line.startsWith("import rp1.") || line.startsWith("import static rp1.")) {
                    offending.add(file + ": " + line);
                }
            }
        }
        assertEquals(List.of(), offending);
    }
}
