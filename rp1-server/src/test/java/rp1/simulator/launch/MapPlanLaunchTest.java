package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsPlan;

/** A map_server YAML file is a floor plan for {@code -f} and {@code floorPlanFileName}. */
class MapPlanLaunchTest {
    @TempDir
    Path dir;

    @Test
    void theShippedMapIsFoundOnTheClassPathWithItsImageBesideIt() throws Exception {
        TestServer.write(dir);
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES, "-f", "rooms.yaml"}, dir,
                LaunchOptions.defaults().withPort(0));
        try {
            RsPlan plan = server.getSimulation().getWorld().getPlan();
            assertTrue(plan.getWallArray().length > 4, "the walls of rooms.pgm");
            assertEquals(plan.getObjectCount(), plan.getWallArray().length);
            assertTrue(plan.getFileName().matches("(file|jar):.*FloorPlans/rooms.yaml"), "read through a class-path URL: "
                    + plan.getFileName());
        } finally {
            server.stop();
        }
    }

    @Test
    void aMapFileErrorStopsTheStartWithFileLineAndColumn() throws Exception {
        TestServer.write(dir, "floorPlanFileName=broken.yaml");
        Files.write(dir.resolve("broken.yaml"), "image: gone.pgm\nresolution: 0.05\n".getBytes(StandardCharsets.UTF_8));
        StartupException e = assertThrows(StartupException.class, () -> ServerLauncher.start(
                new String[] {"-p", TestServer.PROPERTIES}, dir, LaunchOptions.defaults().withPort(0)));
        assertTrue(e.getMessage().matches("(?s).*broken\\.yaml:1:8: Cannot read the map image .*gone\\.pgm: no such file"),
                e.getMessage());
    }
}
