package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Sweep;

/**
 * A sweep closes its engine once every run has ended, and only then: what the engine kept for its
 * runs (the loader the runs shared) is let go when the sweep's runs are over, not when the JVM ends,
 * so a JVM that runs one sweep after another keeps nothing of the ones before.
 */
@Timeout(120)
class EngineLifetimeTest {
    @TempDir
    Path dir;

    @Test
    void theEngineIsClosedOnceAfterItsLastRun() throws IOException {
        Files.write(dir.resolve("home.txt"), List.of("caption: \"open\";", "wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"));
        Files.write(dir.resolve("experiment.ini"), List.of("floorPlanFileName=" + dir.resolve("home.txt"),
                "enableGUI=false", "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max",
                "dlcEnabled=true", "dlcName=" + ExperimentDlc.class.getName(), "exitWhenClientsDone=true",
                "maxSimulationTime=5"));
        List<String> said = Collections.synchronizedList(new ArrayList<>());
        RunEngine.Factory engines = batch -> new Recorded(RunEngine.inThisProcess(List.of(ExperimentDlc.class.getName()),
                EngineLifetimeTest.class.getClassLoader(), 60), said);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Sweep.run(new String[] {"-p", dir.resolve("experiment.ini").toString(), "--seeds", "1-4", "--jobs", "2",
            "--out", dir.resolve("out").toString()}, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(out, true, StandardCharsets.UTF_8), false, new Interruption(), engines);

        assertEquals(0, status, out.toString(StandardCharsets.UTF_8));
        assertEquals(List.of("ran", "ran", "ran", "ran", "closed"), said, "four runs ended, then the engine was closed");
    }

    /** An engine that carries out runs with another and says when a run ended and when it was closed. */
    private static final class Recorded implements RunEngine {
        private final RunEngine engine;
        private final List<String> said;

        Recorded(RunEngine engine, List<String> said) {
            this.engine = engine;
            this.said = said;
        }

        @Override
        public Ran run(Batch.Run run) throws IOException, InterruptedException {
            Ran ran = engine.run(run);
            said.add("ran");
            return ran;
        }

        @Override
        public void stopAll() {
            engine.stopAll();
        }

        @Override
        public boolean firstRunWarmsUp() {
            return engine.firstRunWarmsUp();
        }

        @Override
        public void close() {
            said.add("closed");
            engine.close();
        }
    }
}
