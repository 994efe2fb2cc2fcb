package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.launch.JavaCommand;

/** Nothing a sweep starts outlives it: a --client program's own children, a run in a process of its own. */
@Timeout(60)
class ProcessRunsTest {
    @TempDir
    Path dir;

    @Test
    void stoppingAProgramStopsTheProcessesItStartedToo() throws Exception {
        // A --client script that runs its robot without exec: the robot is the script's child.
        Process script = new ProcessBuilder("sh", "-c", "sleep 300; true").start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (script.descendants().findAny().isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        List<ProcessHandle> robot = script.descendants().toList();
        assertFalse(robot.isEmpty(), "the script started its robot");
        ProcessRuns.stop(script, 2);
        for (ProcessHandle h : robot) {
            h.onExit().get(10, TimeUnit.SECONDS);
            assertFalse(h.isAlive(), "the robot was stopped with its script");
        }
    }

    @Test
    void aRunWhoseSweepWasKilledOutrightStopsItselfAndClosesItsRecording() throws Exception {
        Path plan = Files.writeString(dir.resolve("plan.txt"), "wall w { geometry: 0, 0, 20, 0, 0.05; }\n"
                + "placement p1 { geometry: 2, 2, 0, 0.2; }\n");
        Files.writeString(dir.resolve(SweepRun.PROPERTIES), String.join("\n", "floorPlanFileName=" + plan,
                "dlcEnabled=true", "dlcName=rp1.simulator.launch.TirelessDlc", "simulationSpeed=1", "interlockEnabled=true",
                "maxSimulationTime=300", "enableNetworkClients=false", "enableGUI=false", "logToFile=true",
                "logFileName=" + dir.resolve("server.log"), "recordFileName=" + dir.resolve("recording.txt"), ""));
        // The sweep: a shell that starts the run and waits for it, killed as kill -9 would.
        List<String> command = new ArrayList<>(List.of("sh", "-c", "\"$@\" & echo $!; wait", "sh"));
        command.addAll(JavaCommand.of(List.of(), SweepRun.class.getName(), dir.toString()));
        Process sweep = new ProcessBuilder(command).redirectErrorStream(true).start();
        long runPid;
        try (BufferedReader out = new BufferedReader(new InputStreamReader(sweep.getInputStream(), StandardCharsets.UTF_8))) {
            runPid = Long.parseLong(out.readLine().trim());
            ProcessHandle run = ProcessHandle.of(runPid).orElseThrow();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!Files.exists(dir.resolve("recording.txt.part")) && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            assertTrue(Files.exists(dir.resolve("recording.txt.part")), "the run is going");
            sweep.destroyForcibly();
            run.onExit().get(20, TimeUnit.SECONDS);
        }
        assertTrue(Files.exists(dir.resolve("recording.txt")), "stopped as on Ctrl-C: the recording is whole");
    }
}
