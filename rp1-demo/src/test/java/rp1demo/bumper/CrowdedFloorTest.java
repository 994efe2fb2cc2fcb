package rp1demo.bumper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Collections;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * More Bumpers than the contest floor has room for: those that find no free pose ask again a moment
 * later and then leave, so the run's clock moves on (asking again at once held it at 0 for ever).
 */
@Timeout(60)
class CrowdedFloorTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", ".."));
    private static final int BUMPERS = 40;

    @TempDir
    Path dir;

    @Test
    void bumpersThatFindNoRoomLeaveAndTheRunEndsWhenAsked() throws Exception {
        String properties = "floorPlanFileName=" + ROOT.resolve("FloorPlans/contest.txt").toAbsolutePath() + "\n"
                + "enableGUI=false\nenableNetworkClients=false\ninterlockEnabled=true\nsimulationSpeed=max\n"
                + "randomSeed=1\nmaxSimulationTime=20\ndlcEnabled=true\nlogToSystemOut=false\n"
                + "eventLogFileName=run.events\n"
                + "dlcName=" + String.join(",", Collections.nCopies(BUMPERS, Bumper.class.getName())) + "\n";
        Files.write(dir.resolve("crowd.ini"), properties.getBytes(StandardCharsets.UTF_8));
        RunningServer server = ServerLauncher.start(new String[] {"-p", "crowd.ini"}, dir, LaunchOptions.defaults());
        assertEquals(0, server.awaitExit());
        assertEquals("max-simulation-time", server.getStopReason());
        String events = Files.readString(dir.resolve("run.events"));
        long refused = events.lines().filter(l -> l.contains(" Placement valid=false")).count();
        assertTrue(refused > 0 && refused <= (long) BUMPERS * Bumper.MOST_REFUSALS, "refusals: " + refused);
    }
}
