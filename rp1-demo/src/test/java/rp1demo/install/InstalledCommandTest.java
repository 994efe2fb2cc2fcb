package rp1demo.install;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import javax.tools.ToolProvider;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.simulator.launch.JavaCommand;

/**
 * The installed simulator ({@code gradle installDist}: build/install/rp1) used as a newcomer uses it,
 * from a folder of their own, without a display: every file is relative to that folder, a properties
 * file is honoured headless, a missing one fails, the jar runs with {@code java -jar}, and a robot
 * compiled apart from the simulator runs in a sweep with {@code -cp}. The build passes the
 * installation's folder as {@code rp1.install}.
 */
@Timeout(180)
class InstalledCommandTest {
    private static final String INSTALL = System.getProperty("rp1.install");
    private static final String VERSION = System.getProperty("rp1.version", "0.60.1");

    @TempDir
    Path dir;

    /** What a finished command left: its exit status and everything it printed. */
    private record Result(int status, String output) {
    }

    @BeforeEach
    void installed() {
        assumeTrue(INSTALL != null && Files.isExecutable(Paths.get(INSTALL, "bin", "rp1")),
                "no installed simulator: run through `gradle test`, which installs it first (rp1.install)");
    }

    private Result run(String... command) throws IOException, InterruptedException {
        return runWith(null, command);
    }

    /** Runs the command with {@code JAVA_OPTS} set to {@code javaOptions} (none if null). */
    private Result runWith(String javaOptions, String... command) throws IOException, InterruptedException {
        ProcessBuilder b = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true);
        b.environment().remove("DISPLAY");
        b.environment().remove("JAVA_OPTS");
        b.environment().remove("RP1_OPTS");
        if (javaOptions != null) {
            b.environment().put("JAVA_OPTS", javaOptions);
        }
        b.redirectOutput(dir.resolve("output.txt").toFile());
        Process p = b.start();
        assertTrue(p.waitFor(150, TimeUnit.SECONDS), "the command ended");
        return new Result(p.exitValue(), Files.readString(dir.resolve("output.txt")));
    }

    private Result rp1(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Paths.get(INSTALL, "bin", "rp1").toString()));
        command.addAll(List.of(args));
        return run(command.toArray(new String[0]));
    }

    private void write(String name, String... lines) throws IOException {
        Files.writeString(dir.resolve(name), String.join("\n", lines) + "\n");
    }

    /** The bumper car for 5 simulated seconds, headless, recording into a file named relative to dir. */
    private void bumperProperties() throws IOException {
        write("mine.ini", "floorPlanFileName=contest.txt", "enableGUI=true", "enableNetworkClients=false",
                "interlockEnabled=true", "simulationSpeed=max", "randomSeed=3", "maxSimulationTime=5",
                "dlcEnabled=true", "dlcName=rp1demo.bumper.Bumper", "recordFileName=mine.rec");
    }

    @Test
    void aPropertiesFileRunsHeadlessWithoutADisplayAndItsRecordingReplaysFromTheSameFolder() throws Exception {
        bumperProperties();
        Result server = rp1("-p", "mine.ini");
        assertEquals(0, server.status(), server.output());
        assertTrue(Files.exists(dir.resolve("mine.rec")), "the recording is where the user stands");
        assertTrue(!server.output().contains("fire-fighting"), "the file given ran, not the demo: " + server.output());

        Result replay = rp1("replay", "mine.rec", "--snapshot", "end.png");
        assertEquals(0, replay.status(), replay.output());
        assertTrue(Files.exists(dir.resolve("end.png")));
    }

    @Test
    void theTemplateRobotDrivesOverTcpInTheSimulatorStartedWithAPort() throws Exception {
        Path template = Paths.get(System.getProperty("rp1.root", "..")).resolve("examples/my-robot");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", dir.resolve("classes").toString(),
                "-cp", System.getProperty("java.class.path"),
                template.resolve("src/main/java/mybot/MyRobot.java").toString()));
        Files.copy(template.resolve("rossum.ini"), dir.resolve("rossum.ini"));
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            port = s.getLocalPort();
        }
        ProcessBuilder b = new ProcessBuilder(Paths.get(INSTALL, "bin", "rp1").toString(), "-p", "network.ini",
                "--port", Integer.toString(port)).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("server.txt").toFile());
        b.environment().remove("DISPLAY");
        Process server = b.start();
        try {
            awaitText(dir.resolve("server.txt"), "Socket ready: 127.0.0.1:" + port);
            ProcessBuilder robot = new ProcessBuilder(Paths.get(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", dir.resolve("classes") + java.io.File.pathSeparator + System.getProperty("java.class.path"),
                    "mybot.MyRobot", "-port", Integer.toString(port)).directory(dir.toFile()).redirectErrorStream(true)
                    .redirectOutput(dir.resolve("robot.txt").toFile());
            Process r = robot.start();
            try {
                awaitText(dir.resolve("robot.txt"), "stopped at 1.79");
            } finally {
                r.destroy();
            }
        } finally {
            server.destroy();
            server.waitFor(30, TimeUnit.SECONDS);
        }
    }

    /** The guide's sweep of the template robot: its sweep.ini runs at full speed, each run a fraction of a second. */
    @Test
    void theTemplateRobotSweepsWithItsSweepProperties() throws Exception {
        Path template = Paths.get(System.getProperty("rp1.root", "..")).resolve("examples/my-robot");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", dir.resolve("classes").toString(),
                "-cp", System.getProperty("java.class.path"),
                template.resolve("src/main/java/mybot/MyRobot.java").toString()));
        Files.copy(template.resolve("sweep.ini"), dir.resolve("sweep.ini"));
        Result sweep = rp1("sweep", "-cp", "classes", "-p", "sweep.ini", "--seeds", "1-4", "--out", "sweep");
        assertEquals(0, sweep.status(), sweep.output());
        List<String> rows = Files.readAllLines(dir.resolve("sweep/results.csv"));
        assertEquals(5, rows.size(), rows.toString());
        for (String row : rows.subList(1, 5)) {
            assertTrue(row.contains(",MyRobot,") && row.contains(",30,1,0,") && row.contains(",max-simulation-time,"),
                    "30 simulated seconds, a metre driven, no collision: " + row);
        }
    }

    private static void awaitText(Path file, String text) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!(Files.exists(file) && Files.readString(file).contains(text))) {
            assertTrue(System.nanoTime() < deadline, "no \"" + text + "\" in " + file + ":\n"
                    + (Files.exists(file) ? Files.readString(file) : ""));
            Thread.sleep(50);
        }
    }

    @Test
    void aMissingPropertiesFileIsAnErrorNotTheDemo() throws Exception {
        Result r = rp1("-p", "mybot.ini");
        assertEquals(1, r.status(), r.output());
        assertTrue(r.output().contains("cannot find properties mybot.ini"), r.output());
        assertTrue(!r.output().contains("openjdk version"), "the start script says nothing of its own: " + r.output());
    }

    /**
     * The JVM options of a simulation and of a sweep (JavaCommand says why), and a collector or a
     * compiler setting the user picks instead of ours: two collectors, or one compiler thread for both
     * compilers, would keep the JVM from starting.
     */
    @Test
    void theSimulatorAndTheSweepRunWithTheirOwnOptionsUnlessTheUserPicksACollector() throws Exception {
        String rp1 = Paths.get(INSTALL, "bin", "rp1").toString();
        Result simulation = runWith("-XX:+PrintCommandLineFlags", rp1, "-p", "mybot.ini");
        assertEquals(1, simulation.status(), simulation.output());
        JavaCommand.simulatorOptions().forEach(o -> assertTrue(simulation.output().contains(o), o + " in " + simulation.output()));
        assertEquals(JavaCommand.simulatorOptions().contains(JavaCommand.HUGE_PAGES),
                simulation.output().contains(JavaCommand.HUGE_PAGES), "huge pages as the kernel gives them: " + simulation.output());
        Result sweep = runWith("-XX:+PrintCommandLineFlags", rp1, "sweep", "-h");
        assertEquals(0, sweep.status(), sweep.output());
        // -XX:+PrintCommandLineFlags prints the young generation's size in bytes, as the two flags it sets.
        JavaCommand.SWEEP_OPTIONS.forEach(o -> assertTrue(sweep.output().contains(
                o.equals(JavaCommand.YOUNG_GENERATION) ? "-XX:NewSize=67108864" : o), o + " in " + sweep.output()));
        assertFalse(sweep.output().contains(JavaCommand.HUGE_PAGES), sweep.output());
        int processors = Integer.parseInt(run("getconf", "_NPROCESSORS_ONLN").output().trim());
        assertEquals(processors <= JavaCommand.FEW_PROCESSORS, sweep.output().contains(JavaCommand.ONE_COMPILER_THREAD),
                processors + " processors: " + sweep.output());
        Result theirs = runWith("-XX:+UseParallelGC -XX:+PrintCommandLineFlags", rp1, "-p", "mybot.ini");
        assertEquals(1, theirs.status(), "the simulator started and found no such file: " + theirs.output());
        assertTrue(theirs.output().contains("-XX:+UseParallelGC"), theirs.output());
        assertFalse(theirs.output().contains("-XX:+UseSerialGC"), theirs.output());
        Result smallHeap = runWith("-Xmx48m -XX:+PrintCommandLineFlags", rp1, "sweep", "-h");
        assertEquals(0, smallHeap.status(), smallHeap.output());
        assertFalse(smallHeap.output().contains("-XX:NewSize=67108864") || smallHeap.output().contains("warning"),
                "a heap the user sizes has no young generation of ours, larger than it: " + smallHeap.output());
        Result bothCompilers = runWith("-XX:TieredStopAtLevel=4 -XX:+PrintCommandLineFlags", rp1, "sweep", "-h");
        assertEquals(0, bothCompilers.status(), "one compiler thread would keep both compilers from starting: "
                + bothCompilers.output());
        assertFalse(bothCompilers.output().contains(JavaCommand.ONE_COMPILER_THREAD), bothCompilers.output());
    }

    @Test
    void theServerJarRunsWithJavaDashJar() throws Exception {
        bumperProperties();
        Path jar = Paths.get(INSTALL, "lib", "rp1-server-" + VERSION + ".jar");
        Result r = run(Paths.get(System.getProperty("java.home"), "bin", "java").toString(), "-jar", jar.toString(),
                "-p", "mine.ini");
        assertEquals(0, r.status(), r.output());
        assertTrue(Files.exists(dir.resolve("mine.rec")));
    }

    /** A robot compiled apart into dir/classes, and still.ini, which loads it. */
    private void stillRobot() throws IOException {
        robot("Still", "classes", "A robot that places itself and stands still.", "");
        robotProperties("still.ini", "mybot.Still");
    }

    /** Properties that run the robot {@code className} in the White Room for 2 s, headless, at once. */
    private void robotProperties(String file, String className) throws IOException {
        write(file, "floorPlanFileName=WhiteRoom.txt", "enableGUI=false", "enableNetworkClients=false",
                "interlockEnabled=true", "simulationSpeed=max", "maxSimulationTime=2", "dlcEnabled=true",
                "dlcName=" + className);
    }

    /**
     * Compiles robot mybot.NAME into dir/FOLDER: it runs {@code more} (Java statements, and class body
     * declarations before them), then places a disc at "home".
     */
    private void robot(String name, String folder, String comment, String declarations, String... more)
            throws IOException {
        Path source = dir.resolve("src/mybot/" + name + ".java");
        Files.createDirectories(source.getParent());
        List<String> lines = new ArrayList<>(List.of(
                "package mybot;",
                "/** " + comment + " */",
                "public class " + name + " extends rp1.rossum.RsClient {",
                declarations,
                "    @Override public void initialize() throws java.io.IOException {",
                "        super.initialize();"));
        lines.addAll(List.of(more));
        lines.addAll(List.of(
                "        rp1.rossum.RsBody body = new rp1.rossum.RsBody(\"" + name.toLowerCase(Locale.ROOT) + "\");",
                "        body.addPart(new rp1.rossum.RsBodyCircle(0.0, 0.0, 0.15));",
                "        sendBodySpecification(body);",
                "        sendPlacementRequest(\"home\");",
                "    }",
                "}"));
        Files.writeString(source, String.join("\n", lines), StandardCharsets.UTF_8);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", dir.resolve(folder).toString(),
                "-cp", System.getProperty("java.class.path"), source.toString()));
    }

    @Test
    void aRobotCompiledApartRunsInASweepWithItsClassPath() throws Exception {
        stillRobot();
        Result r = rp1("sweep", "-p", "still.ini", "--seeds", "1-2", "--jobs", "2", "--out", "out", "-cp", "classes");
        assertEquals(0, r.status(), r.output());
        List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
        assertEquals(3, rows.size(), rows.toString());
        List<String> header = List.of(rows.get(0).split(","));
        String[] row = rows.get(1).split(",");
        assertEquals("0", row[header.indexOf("status")], "exit status of " + rows.get(1));

        // A JVM per run gets the robot's classes too.
        Result apart = rp1("sweep", "-p", "still.ini", "--seeds", "1", "--isolation", "process", "--out", "apart",
                "-cp", "classes");
        assertEquals(0, apart.status(), apart.output());
    }

    @Test
    void theRunsShareARobotsClassesOnlyWhenNoneKeepsStateInAStaticField() throws Exception {
        stillRobot();
        Result still = rp1("sweep", "-p", "still.ini", "--seeds", "1-2", "--out", "still", "-cp", "classes");
        assertEquals(0, still.status(), still.output());
        assertTrue(still.output().contains("the runs shared the robot's classes: none keeps state in a static field"),
                still.output());

        // A robot that counts its runs in a static field: each run must still find it at 0.
        robot("Counting", "counting-classes", "A robot that counts its runs in a static field, and reports the count.",
                "    static int runs;", "        reportRunResult(\"runs_seen\", ++runs);");
        robotProperties("counting.ini", "mybot.Counting");
        Result counting = rp1("sweep", "-p", "counting.ini", "--seeds", "1-4", "--jobs", "2", "--out", "counting",
                "-cp", "counting-classes");
        assertEquals(0, counting.status(), counting.output());
        assertTrue(counting.output().contains("each run loaded the robot's classes anew: mybot.Counting.runs can keep"
                + " state in a static field"), counting.output());
        List<String> rows = Files.readAllLines(dir.resolve("counting/results.csv"));
        int column = List.of(rows.get(0).split(",")).indexOf("result.runs_seen");
        assertTrue(column >= 0, rows.get(0));
        for (String row : rows.subList(1, rows.size())) {
            assertEquals("1", row.split(",")[column], "every run starts with the static field at 0: " + rows);
        }
        assertEquals(5, rows.size(), rows.toString());
    }

    @Test
    void onSparkTheRobotsClassesTravelWithTheJobAndTheRowsAreTheSweepsOwn() throws Exception {
        stillRobot();
        assertEquals(0, rp1("sweep", "-p", "still.ini", "--seeds", "1-3", "--out", "own", "-cp", "classes").status());
        Result r = rp1("sweep", "-p", "still.ini", "--seeds", "1-3", "--out", "spark", "-cp", "classes",
                "--master", "local[2]");
        assertEquals(0, r.status(), r.output());
        assertEquals(withoutWallTime(dir.resolve("own/results.csv")), withoutWallTime(dir.resolve("spark/results.csv")));
        assertTrue(Files.exists(dir.resolve("spark/runs/2-WhiteRoom/recording.txt")), "the run's files came back");
    }

    @Test
    void withoutMasterNoSparkClassIsOnTheCommandsClassPath() throws Exception {
        String script = Files.readString(Paths.get(INSTALL, "bin", "rp1"));
        String classPath = script.lines().filter(l -> l.startsWith("CLASSPATH=")).findFirst().orElseThrow();
        assertFalse(classPath.contains("spark"), classPath);
        assertTrue(Files.isDirectory(Paths.get(INSTALL, "lib", "spark")), "the Spark module is installed apart");
    }

    /** The rows of a results.csv without their wall-clock time, which no two runs share. */
    private static List<String> withoutWallTime(Path results) throws IOException {
        List<String> lines = Files.readAllLines(results);
        int wall = List.of(lines.get(0).split(",")).indexOf("wall_seconds");
        List<String> rows = new ArrayList<>();
        for (String line : lines) {
            List<String> cells = new ArrayList<>(List.of(line.split(",", -1)));
            cells.remove(wall);
            rows.add(String.join(",", cells));
        }
        return rows;
    }
}
