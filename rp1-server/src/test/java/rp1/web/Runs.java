package rp1.web;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/** Runs of {@link Wanderer} in the White Room for the page's tests, through the real server. */
final class Runs {
    private Runs() {
    }

    /** The properties of a headless lockstep run of the wanderer to {@code seconds}, plus {@code more}. */
    static Path properties(Path dir, double seconds, String... more) throws IOException {
        List<String> lines = new ArrayList<>(List.of("floorPlanFileName=WhiteRoom.txt", "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max", "randomSeed=3",
                "maxSimulationTime=" + seconds, "dlcEnabled=true", "dlcName=" + Wanderer.class.getName(),
                "logToFile=true", "logFileName=server.log"));
        lines.addAll(List.of(more));
        return Files.write(dir.resolve("run.ini"), String.join("\n", lines).getBytes(StandardCharsets.UTF_8));
    }

    /** Starts the server of {@link #properties}. */
    static RunningServer start(Path dir, LaunchOptions options) throws Exception {
        return ServerLauncher.start(new String[] {"-p", "run.ini"}, dir, options);
    }

    /** Records a run of {@code seconds} into {@code dir/run.rec} (and its event log, run.events). */
    static Path record(Path dir, double seconds, String... more) throws Exception {
        List<String> lines = new ArrayList<>(List.of("recordFileName=run.rec", "eventLogFileName=run.events"));
        lines.addAll(List.of(more));
        properties(dir, seconds, lines.toArray(new String[0]));
        RunningServer server = start(dir, LaunchOptions.defaults());
        if (server.awaitExit(60, TimeUnit.SECONDS).isEmpty()) {
            server.stop();
            throw new AssertionError("the recorded run did not end in 60 s");
        }
        return dir.resolve("run.rec");
    }
}
