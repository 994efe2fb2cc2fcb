package rp1.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;
import rp1.simulator.launch.StartupException;

/** Servers for the benchmarks: headless, on a free port, logging to a temporary directory. */
final class BenchServer {
    private BenchServer() {
    }

    /** Starts a server with these properties (after headless, silent defaults). */
    static RunningServer start(String... lines) throws IOException, StartupException {
        Path dir = Files.createTempDirectory("rp1-bench");
        dir.toFile().deleteOnExit();
        Path log = dir.resolve("bench.log");
        log.toFile().deleteOnExit();
        StringBuilder props = new StringBuilder("enableGUI=false\nlogToFile=true\nlogFileName=bench.log\n"
                + "logToSystemOut=false\nfloorPlanFileName=WhiteRoom.txt\nrandomSeed=1\n");
        for (String line : lines) {
            props.append(line).append('\n');
        }
        Path file = dir.resolve("bench.ini");
        Files.write(file, props.toString().getBytes(StandardCharsets.UTF_8));
        file.toFile().deleteOnExit();
        return ServerLauncher.start(new String[] {"-p", "bench.ini"}, dir, LaunchOptions.defaults().withPort(0));
    }
}
