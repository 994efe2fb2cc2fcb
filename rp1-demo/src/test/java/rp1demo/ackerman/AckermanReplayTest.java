package rp1demo.ackerman;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * The Ackerman car's course recorded and replayed: the same events, byte for byte. The recording held
 * the car's steering limit as the simulator had derived it, which the replay derived again, smaller:
 * the replayed car turned less tightly, ran into a wall at 11.9 s, and the replay ended short.
 */
@Timeout(60)
class AckermanReplayTest {
    @TempDir
    Path dir;

    @Test
    void theCarsCourseReplaysToTheSameEvents() throws Exception {
        Files.writeString(dir.resolve("car.ini"), String.join("\n", "floorPlanFileName=ackerman.txt", "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max", "randomSeed=1",
                "maxSimulationTime=30", "logToSystemOut=false", "dlcEnabled=true", "dlcName=" + Main.class.getName(),
                "recordFileName=car.rec", "eventLogFileName=car.events", ""));
        RunningServer server = ServerLauncher.start(new String[] {"-p", "car.ini"}, dir, LaunchOptions.defaults());
        assertEquals(0, server.awaitExit());

        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {dir.resolve("car.rec").toString(), "--events",
            dir.resolve("replay.events").toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(out, true, StandardCharsets.UTF_8));
        assertEquals(0, status, out.toString(StandardCharsets.UTF_8));
        assertEquals(Files.readString(dir.resolve("car.events")), Files.readString(dir.resolve("replay.events")));
    }
}
