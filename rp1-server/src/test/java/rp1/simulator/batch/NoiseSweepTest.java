package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** A sweep varies the noise keys like any other: one configuration per value, each its own noise. */
@Timeout(120)
class NoiseSweepTest {
    @TempDir
    Path dir;
    private final InProcessSweep sweeps = new InProcessSweep();

    private Path properties() throws Exception {
        Files.write(dir.resolve("home.txt"), List.of("caption: \"open\";", "wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }"));
        return Files.write(dir.resolve("noisy.ini"), List.of("floorPlanFileName=" + dir.resolve("home.txt"),
                "enableGUI=false", "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max",
                "dlcEnabled=true", "dlcName=" + ExperimentDlc.class.getName(), "exitWhenClientsDone=true",
                "maxSimulationTime=30"));
    }

    @Test
    void slipVariedBySweepMovesWhereTheRobotEnds() throws Exception {
        int status = sweeps.run("-p", properties().toString(), "--seeds", "1", "--vary",
                "noiseSlipDistanceSigma=0,0.3", "--jobs", "1", "--out", dir.resolve("out").toString());
        assertEquals(0, status, sweeps.out() + sweeps.err());
        List<List<String>> t = CsvText.rows(Files.readString(dir.resolve("out").resolve("results.csv")));
        List<String> header = t.get(0);
        assertEquals("noiseSlipDistanceSigma", header.get(0));
        assertEquals(3, t.size(), t.toString());
        int endX = header.indexOf("end_x");
        assertEquals(1.4, Double.parseDouble(t.get(1).get(endX)), 1e-3, "0.2 m/s for 2 s from x = 1, exactly");
        assertNotEquals(t.get(1).get(endX), t.get(2).get(endX), "the slipping robot ends elsewhere");
    }

    @Test
    void aNoiseValueOutOfRangeIsRefusedNamingTheKey() throws Exception {
        int status = sweeps.run("-p", properties().toString(), "--seeds", "1", "--vary", "noiseRangeDropout=0,2",
                "--out", dir.resolve("bad").toString());
        assertTrue(status != 0, sweeps.out());
        assertTrue(sweeps.err().contains("noiseRangeDropout"), sweeps.err());
    }
}
