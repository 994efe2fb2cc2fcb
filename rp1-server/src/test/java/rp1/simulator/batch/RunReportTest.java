package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.StringReader;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.outcome.RobotResult;

/** A run's result.txt: what the sweep reads back is what the run wrote, whatever its robots are called. */
class RunReportTest {

    @Test
    void aReportReadsBackAsItWasWrittenWithOddNamesAndResults(@TempDir Path dir) throws Exception {
        RobotResult robot = new RobotResult(" Bümper = #1: a\\b!", new RobotResult.Pose(1.25, -2.5, 0.1),
                new RobotResult.Pose(Double.NaN, Double.NaN, Double.NaN), 8.3859, 15, 2.452, 45,
                Map.of("tour time", 12.5, "ratio:x", Double.NaN));
        RunReport report = new RunReport(60.0, "client failed: boom\nat line 2", 2, List.of(robot));
        report.write(dir);
        assertEquals(report, RunReport.read(dir));
    }

    @Test
    void theParametersTheRobotsAskedForReadBackAndUnknownStaysUnknown(@TempDir Path dir) throws Exception {
        RunReport asked = new RunReport(30.0, "clients-done", 0, List.of(), List.of("speed", "place"));
        asked.write(dir);
        assertEquals(asked, RunReport.read(dir));
        RunReport none = new RunReport(30.0, "clients-done", 0, List.of(), List.of());
        none.write(dir);
        assertEquals(List.of(), RunReport.read(dir).parametersAsked());
        RunReport unknown = new RunReport(30.0, "clients-done", 0, List.of());
        unknown.write(dir);
        assertEquals(null, RunReport.read(dir).parametersAsked(), "a --client program's run");
    }

    @Test
    void entriesAreEscapedSoThatPropertiesLoadReadsThemBack() throws Exception {
        Random random = new Random(11);
        String alphabet = " =:#!\\\t\n\r\fabc.,é€\u0001\u007f\u00a0xyz";
        for (int round = 0; round < 500; round++) {
            Map<String, String> entries = new LinkedHashMap<>();
            for (int i = 0; i < 6; i++) {
                entries.put(word(random, alphabet, 1 + random.nextInt(8)), word(random, alphabet, random.nextInt(10)));
            }
            Properties loaded = new Properties();
            loaded.load(new StringReader(PropertiesText.of(entries)));
            Map<String, String> back = new LinkedHashMap<>();
            loaded.stringPropertyNames().forEach(k -> back.put(k, loaded.getProperty(k)));
            assertEquals(entries, back, PropertiesText.of(entries));
        }
    }

    private static String word(Random random, String alphabet, int length) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < length; i++) {
            b.append(alphabet.charAt(random.nextInt(alphabet.length())));
        }
        return b.toString();
    }
}
