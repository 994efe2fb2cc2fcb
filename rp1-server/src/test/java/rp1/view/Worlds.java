package rp1.view;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.snapshot.WorldSnapshot;

/** Plans, configurations, logs and snapshots for the view's tests. */
final class Worlds {
    private Worlds() {
    }

    static Path floorPlan(String name) {
        return Paths.get(System.getProperty("rp1.root", ".")).resolve("FloorPlans").resolve(name);
    }

    static String whiteRoomText() throws IOException {
        return Files.readString(floorPlan("WhiteRoom.txt"));
    }

    static RsPlan whiteRoom() throws IOException, RsParsingException {
        return plan("WhiteRoom.txt");
    }

    /** One of the plans in FloorPlans/, parsed. */
    static RsPlan plan(String name) throws IOException, RsParsingException {
        return RsPlanParser.parseFile(floorPlan(name));
    }

    /** A server configuration for the WhiteRoom with these extra keys (key, value, key, value, ...). */
    static ServerConfig config(String... keysAndValues) throws ConfigException {
        Properties p = new Properties();
        p.setProperty("floorPlanFileName", "WhiteRoom.txt");
        for (int i = 0; i < keysAndValues.length; i += 2) {
            p.setProperty(keysAndValues[i], keysAndValues[i + 1]);
        }
        return ServerConfig.from(p, "test", null);
    }

    /** A snapshot taken on the thread running tasks (whose clock must be running), waiting up to 10 s. */
    static WorldSnapshot capture(Simulation simulation) throws Exception {
        CompletableFuture<WorldSnapshot> f = new CompletableFuture<>();
        simulation.getScheduler().observeNow(t -> f.complete(WorldSnapshot.of(simulation.getWorld(), t)));
        return f.get(10, TimeUnit.SECONDS);
    }

    /** A log that keeps its lines. */
    static final class RecordingLog extends RsLogAdapter {
        private final List<String> lines = new ArrayList<>();

        @Override
        public synchronized void logIt(String level, String message) {
            lines.add(level + " " + message);
        }

        synchronized List<String> lines() {
            return new ArrayList<>(lines);
        }
    }
}
