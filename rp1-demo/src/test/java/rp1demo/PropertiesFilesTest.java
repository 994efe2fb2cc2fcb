package rp1demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.lang.reflect.Modifier;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

import org.junit.jupiter.api.Test;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsRunnable;
import rp1.simulator.config.ServerConfig;

/**
 * The shipped Properties/*.ini files: each is a valid server configuration whose floor plan parses
 * and whose in-process robots can be loaded the way the server loads them (a public class
 * implementing RsRunnable with a public no-argument constructor).
 */
class PropertiesFilesTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", ".."));
    private static final List<String> DEMOS = List.of(
            "clientzero.ini", "demozero.ini", "linetracker.ini", "ackerman.ini", "firefighter.ini", "autopilot.ini");

    private static ServerConfig config(String name) throws Exception {
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(ROOT.resolve("Properties").resolve(name))) {
            p.load(in);
        }
        return ServerConfig.from(p, name, null);
    }

    private static List<String> allFiles() throws IOException {
        List<String> names = new ArrayList<>();
        try (DirectoryStream<Path> dir = Files.newDirectoryStream(ROOT.resolve("Properties"), "*.ini")) {
            for (Path p : dir) {
                names.add(p.getFileName().toString());
            }
        }
        return names;
    }

    @Test
    void everyFileIsAValidConfigurationWhosePlanParsesAndWhoseRobotsCanBeLoaded() throws Exception {
        List<String> names = allFiles();
        assertTrue(names.containsAll(DEMOS) && names.contains("RP1.ini") && names.contains("headless.ini"), names.toString());
        for (String name : names) {
            ServerConfig c = config(name);
            RsPlanParser.parseFile(ROOT.resolve("FloorPlans").resolve(c.floorPlanFileName));
            for (String className : c.dlcNames) {
                Class<?> k = Class.forName(className);
                assertTrue(RsRunnable.class.isAssignableFrom(k), name + ": " + className + " is not an RsRunnable");
                assertTrue(Modifier.isPublic(k.getModifiers()) && Modifier.isPublic(k.getConstructor().getModifiers()),
                        name + ": " + className + " needs to be public with a public no-argument constructor");
            }
        }
    }

    @Test
    void theDefaultIsClientZeroInAWindowAtRealSpeedWithNetworkClientsAndLogOnTheConsole() throws Exception {
        ServerConfig c = config("RP1.ini");
        assertTrue(c.enableGUI && c.enableNetworkClients && c.logToSystemOut && c.dlcEnabled);
        assertFalse(c.interlockEnabled);
        assertEquals(1.0, c.simulationSpeed);
        assertEquals(List.of("rp1demo.clientzero.ClnMain"), c.dlcNames);
    }

    @Test
    void eachDemoLoadsItsRobotInAWindowAtRealSpeed() throws Exception {
        for (String name : DEMOS) {
            ServerConfig c = config(name);
            assertTrue(c.dlcEnabled && c.enableGUI, name);
            assertEquals(1, c.dlcNames.size(), name);
            assertEquals(1.0, c.simulationSpeed, name);
        }
    }

    @Test
    void theHeadlessDemoRunsAsFastAsItCanStopsByItselfAndLeavesAPicture() throws Exception {
        ServerConfig c = config("headless.ini");
        assertFalse(c.enableGUI);
        assertTrue(c.lockstep && c.interlockEnabled && c.logToSystemOut);
        assertTrue(c.maxSimulationTime < Double.POSITIVE_INFINITY || c.exitWhenClientsDone);
        assertTrue(c.snapshotFileName != null && c.snapshotFileName.endsWith(".png"));
        assertEquals(List.of("rp1demo.firefighter.FfMain"), c.dlcNames);
    }
}
