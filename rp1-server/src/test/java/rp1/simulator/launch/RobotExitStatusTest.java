package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A server whose loaded robot calls {@code System.exit(3)} in the middle of its run ends with the
 * run's status, {@link ExitStatus#CLIENT_FAILED}, not the robot's 3 (or a 0 that would pass for a
 * run that went as asked), its log saying where the robot called it and its event log whole.
 */
@Timeout(120)
class RobotExitStatusTest {
    @TempDir
    Path dir;

    @Test
    void aRobotThatCallsSystemExitEndsTheServerWithTheFailedRunsStatus() throws Exception {
        Files.write(dir.resolve("home.txt"), List.of("wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"));
        Files.write(dir.resolve("exit.ini"), List.of("floorPlanFileName=home.txt", "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max", "dlcEnabled=true",
                "dlcName=rp1.simulator.batch.ExitingDlc", "maxSimulationTime=30", "logToFile=true",
                "logFileName=server.log", "eventLogFileName=events.txt"));
        File output = dir.resolve("output.txt").toFile();
        Process p = new ProcessBuilder(JavaCommand.of(List.of(), "rp1.Server", "-p", "exit.ini"))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(output).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the server ended");
        String log = Files.readString(dir.resolve("server.log"));
        assertEquals(ExitStatus.CLIENT_FAILED, p.exitValue(), log + Files.readString(output.toPath()));
        assertTrue(log.contains("A robot called System.exit in rp1.simulator.batch.ExitingDlc.quit"), log);
        assertTrue(Files.exists(dir.resolve("events.txt")), "the event log was closed under its own name");
    }
}
