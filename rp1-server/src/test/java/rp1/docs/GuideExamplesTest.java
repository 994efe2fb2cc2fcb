package rp1.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;

/**
 * The example clients of docs/guide.md compile as they stand, and do what the guide says they do: the
 * guide's Explorer and Wanderer run loaded into a headless lockstep server on the guide's hall, started
 * the way {@code java rp1.Server -p FILE} starts one, and what they print is compared with the guide.
 */
@Timeout(120)
class GuideExamplesTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", "."));

    @TempDir
    Path dir;

    private final GuideText guide;

    GuideExamplesTest() throws IOException {
        guide = GuideText.read(ROOT);
    }

    @Test
    void everyJavaExampleInTheGuideCompiles() throws IOException {
        List<String> examples = guide.javaExamples();
        assertTrue(examples.size() >= 3, "found only " + examples.size() + " Java examples in docs/guide.md");
        ExampleCompiler.compile(examples, dir);
    }

    @Test
    void theExplorerPrintsWhatTheGuideShows() throws Exception {
        String printed = run("mybot.Explorer", List.of(), "exitWhenClientsDone=true");
        assertEquals(guide.block("explorer-output"), printed);
    }

    @Test
    void theWandererStartedAgainstAWallWaitsOnceAndWandersOn() throws Exception {
        String docked = "package mybot;\n\npublic class DockedWanderer extends Wanderer {\n"
                + "    public DockedWanderer() {\n        super(\"dock\");\n    }\n}\n";
        String printed = run("mybot.DockedWanderer", List.of(docked), "maxSimulationTime=120");
        assertEquals(guide.block("wanderer-output"), printed,
                "blocked at its start once, then free; in lockstep a spin would never reach 120 s");
    }

    /**
     * The guide's first client bumps into the hall's walls again and again and drives on each time: a
     * handler that asked for a turn on the spot after a bump was blocked at once, for ever, and in
     * lockstep the run never reached its end.
     */
    @Test
    void theBumperBumpsAndDrivesOnForMinutes() throws Exception {
        run("mybot.Bumper", List.of(), "maxSimulationTime=600");
        // What a loaded client logs goes to the server's log.
        String log = log();
        long bumps = log.lines().filter(l -> l.contains("; backing off")).count();
        assertTrue(bumps >= 10, "bumped " + bumps + " times in 600 s:\n" + log);
    }

    /**
     * Runs {@code client}, one of the guide's examples or of {@code extraSources}, loaded into a server
     * with the guide's hall and the {@code settings} that make it stop, and returns what the client
     * printed on standard output.
     */
    private String run(String client, List<String> extraSources, String... settings) throws Exception {
        List<String> sources = new ArrayList<>(guide.javaExamples());
        sources.addAll(extraSources);
        ClassLoader classes = ExampleCompiler.compile(sources, dir);
        Files.write(dir.resolve("hall.txt"), guide.block("hall.txt").getBytes(StandardCharsets.UTF_8));
        Files.write(dir.resolve("guide.ini"), properties(client, settings).getBytes(StandardCharsets.UTF_8));
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        PrintStream out = System.out;
        Thread self = Thread.currentThread();
        ClassLoader previous = self.getContextClassLoader();
        RunningServer server = null;
        try {
            System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
            self.setContextClassLoader(classes);
            server = ServerLauncher.start(new String[] {"-p", "guide.ini"}, dir, LaunchOptions.defaults().withPort(0));
            OptionalInt status = server.awaitExit(60, TimeUnit.SECONDS);
            assertTrue(status.isPresent(), "the server did not stop by itself; printed so far:\n" + printed);
            assertEquals(ExitStatus.OK, status.getAsInt(), log());
        } finally {
            System.setOut(out);
            self.setContextClassLoader(previous);
            if (server != null) {
                server.stop();
            }
        }
        return printed.toString(StandardCharsets.UTF_8);
    }

    private static String properties(String client, String... settings) {
        StringBuilder p = new StringBuilder(String.join("\n",
                "floorPlanFileName=hall.txt", "enableGUI=false", "enableNetworkClients=false",
                "simulationSpeed=max", "interlockEnabled=true", "randomSeed=1",
                "dlcEnabled=true", "dlcName=" + client,
                "logToFile=true", "logFileName=server.log", "logToSystemOut=false", ""));
        for (String setting : settings) {
            p.append(setting).append('\n');
        }
        return p.toString();
    }

    private String log() throws IOException {
        Path log = dir.resolve("server.log");
        return Files.exists(log) ? new String(Files.readAllBytes(log), StandardCharsets.UTF_8) : "(no log)";
    }
}
