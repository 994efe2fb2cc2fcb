package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import rp1.Sweep;
import rp1.planparser.RsPlanParser;

/** Sweeps refused before they start, and a run that fails among runs that do not. */
@Timeout(60)
class SweepTest {
    @TempDir
    Path dir;
    private final InProcessSweep sweeps = new InProcessSweep();

    private int sweep(String... args) {
        return sweeps.run(args);
    }

    private Path write(String name, String... lines) throws IOException {
        return Files.write(dir.resolve(name), (String.join("\n", lines) + "\n").getBytes(StandardCharsets.UTF_8));
    }

    private Path properties(String... extra) throws IOException {
        write("home.txt", "caption: \"with home\";", "wall w { geometry: 0, 0, 4, 0, 0.05; }",
                "placement home { geometry: 1, 1, 0, 0.2; }");
        write("bare.txt", "caption: \"without home\";", "wall w { geometry: 0, 0, 4, 0, 0.05; }",
                "placement elsewhere { geometry: 1, 1, 0, 0.2; }");
        String[] lines = {"floorPlanFileName=" + dir.resolve("home.txt"), "enableGUI=false",
            "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max",
            "dlcEnabled=true", "dlcName=" + PickyDlc.class.getName()};
        String[] all = new String[lines.length + extra.length];
        System.arraycopy(lines, 0, all, 0, lines.length);
        System.arraycopy(extra, 0, all, lines.length, extra.length);
        return write("picky.ini", all);
    }

    @Test
    void propertiesThatDoNotBoundARunAreRefusedNamingTheKeysToSet() throws Exception {
        Path p = properties();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1-2", "--out", dir.resolve("out").toString()));
        assertEquals("rp1.Sweep: " + p + ": neither maxSimulationTime nor exitWhenClientsDone is set, so a run might"
                + " never end: set maxSimulationTime=SECONDS (or exitWhenClientsDone=true)\n",
                sweeps.err());
        assertTrue(Files.notExists(dir.resolve("out")), "nothing was run");
    }

    @Test
    void aMistypedOptionIsNamedWithTheOneItWasMeantToBe() {
        assertEquals(1, sweep("-p", "x.ini", "--sed", "1", "--out", dir.resolve("out").toString()));
        assertTrue(sweeps.err().startsWith("rp1.Sweep: unknown option --sed; did you mean --seeds?\n"), sweeps.err());
    }

    @Test
    void propertiesThatLoadNoRobotAreRefused() throws Exception {
        Path p = write("none.ini", "floorPlanFileName=" + dir.resolve("x.txt"), "maxSimulationTime=10");
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--out", dir.resolve("out").toString()));
        assertTrue(sweeps.err().contains("no robot is loaded: set dlcEnabled=true and"
                + " dlcName=CLASS"), sweeps.err());
    }

    @Test
    void aRunThatFailsIsARowWithItsReasonAndTheOtherRunsGoOn() throws Exception {
        Path p = properties("exitWhenClientsDone=true", "maxSimulationTime=30");
        int status = sweep("-p", p.toString(), "--seeds", "5", "--plans", dir.resolve("bare.txt") + ","
                + dir.resolve("home.txt"), "--jobs", "2", "--out", dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
        assertEquals("seed,plan,run,robot,start_x,start_y,start_heading,end_x,end_y,end_heading,end_time,distance,"
                + "collisions,first_collision_time,events,status,reason,wall_seconds", rows.get(0));
        assertEquals(3, rows.size(), rows.toString());
        assertTrue(rows.get(1).startsWith("5," + dir.resolve("bare.txt") + ",runs/5-bare,picky,,,,,,,0,0,0,,1,2,"
                + "\"client failed: client " + PickyDlc.class.getName() + ": a handler failed: java.lang.Error: no"
                + " placement \"\"home\"\" on this floor plan\","), rows.get(1));
        assertTrue(rows.get(2).startsWith("5," + dir.resolve("home.txt") + ",runs/5-home,picky,1,1,0,1,1,0,0,0,0,,1,0,"
                + "clients-done,"), rows.get(2));
        assertTrue(Files.exists(dir.resolve("out/runs/5-home/recording.txt")));
        assertTrue(Files.exists(dir.resolve("out/summary.png")));
    }

    @Test
    void aSummaryPictureThatCannotBeWrittenFailsTheSweepAndTheIndexShowsNone() throws Exception {
        // The picture is drawn while the tables and index.html are written: the index, written first,
        // must not keep showing a picture that then failed.
        Path p = properties("exitWhenClientsDone=true", "maxSimulationTime=30");
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1-2", "--out", dir.resolve("out").toString()), sweeps.err());
        Files.delete(dir.resolve("out/summary.png"));
        Files.createDirectories(dir.resolve("out/summary.png/in-the-way"));
        sweeps.reset();
        int status = sweep("-p", p.toString(), "--seeds", "1-2", "--out", dir.resolve("out").toString(), "--resume");
        assertEquals(1, status, sweeps.out() + sweeps.err());
        assertTrue(sweeps.err().startsWith("rp1.Sweep: " + dir.resolve("out/summary.png")), sweeps.err());
        assertEquals(3, Files.readAllLines(dir.resolve("out/results.csv")).size());
        assertTrue(Files.exists(dir.resolve("out/summary.csv")));
        String index = Files.readString(dir.resolve("out/index.html"));
        assertTrue(index.contains("\"picture\":0,"), index);
    }

    @Test
    void aRunThatOutlivesItsTimeoutIsStoppedAndIsARowWithItsReason() throws Exception {
        Path p = properties("exitWhenClientsDone=true", "dlcName=" + SleepyDlc.class.getName());
        int status = sweep("-p", p.toString(), "--seeds", "2", "--timeout", "2", "--out", dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
        assertTrue(rows.get(1).startsWith("2," + dir.resolve("home.txt") + ",runs/2-home,"), rows.get(1));
        assertTrue(rows.get(1).contains(",124,timeout: still running after 2 s of wall time,"), rows.get(1));
    }

    @Test
    void aFirstRunThatHangsHoldsTheOtherJobsBackForASecondNotUntilItsTimeout() throws Exception {
        // The first run goes alone to warm the process up; one that hangs (or runs for minutes) used to
        // leave the other job idle until it ended.
        Path p = properties("exitWhenClientsDone=true", "dlcName=" + SleepyDlc.class.getName());
        int status = sweep("-p", p.toString(), "--seeds", "1-2", "--jobs", "2", "--timeout", "3", "--out",
                dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        FileTime secondStarted = Files.getLastModifiedTime(dir.resolve("out/runs/2-home/run.ini"));
        FileTime firstEnded = Files.getLastModifiedTime(dir.resolve("out/runs/1-home/result.txt"));
        assertTrue(secondStarted.compareTo(firstEnded) < 0, "run 2 started at " + secondStarted
                + ", run 1 ended at " + firstEnded);
    }

    @ParameterizedTest
    @ValueSource(classes = {SpinningHandlerDlc.class, SpinningRunDlc.class})
    void aRobotThatComputesForEverIsStoppedWithItsRunInsteadOfKeepingAProcessorBusy(Class<?> robot) throws Exception {
        // In a handler the simulation calls, it holds the simulation's thread; in run(), its own. Either
        // would go on through every later run of the sweep's process.
        Path p = properties("exitWhenClientsDone=true", "dlcName=" + robot.getName());
        int status = sweep("-p", p.toString(), "--seeds", "1-2", "--jobs", "2", "--timeout", "1", "--out",
                dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
        assertEquals(3, rows.size(), rows.toString());
        assertTrue(rows.get(2).contains(",124,timeout: still running after 1 s of wall time,"), rows.get(2));
        List<String> spinning = new ArrayList<>();
        Thread.getAllStackTraces().forEach((thread, stack) -> {
            if (Arrays.stream(stack).anyMatch(f -> f.getClassName().startsWith(SpinningHandlerDlc.class.getName()))) {
                spinning.add(thread.getName());
            }
        });
        assertEquals(List.of(), spinning, "threads still running the robot's code");
        String log = Files.readString(dir.resolve("out/runs/1-home/server.log"));
        assertTrue(log.contains(" in " + SpinningHandlerDlc.class.getName() + ".spin(SpinningHandlerDlc.java:"), log);
        assertTrue(log.contains("): stopped\n"), log);
    }

    @Test
    void aRobotThatCatchesTheStopSendsTheRunsAfterItToProcessesOfTheirOwn() throws Exception {
        Path flag = write("keep-catching", "while this file is here");
        Path p = properties("exitWhenClientsDone=true", "dlcName=" + CatchingDlc.class.getName(), "param.flag=" + flag);
        try {
            // One job, so that the first run has ended (and left its thread) before the next starts: with
            // more, the runs started beside it before it ended stay in the sweep's process too.
            int status = sweep("-p", p.toString(), "--seeds", "1-3", "--jobs", "1", "--timeout", "1", "--out",
                    dir.resolve("out").toString());
            assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
            List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
            assertEquals(4, rows.size(), rows.toString());
            for (String row : rows.subList(1, 4)) {
                assertTrue(row.contains(",124,timeout: still running after 1 s of wall time,"), row);
            }
            // The first run goes in the sweep's process; the two after it, each in a process of its own.
            assertTrue(Files.notExists(dir.resolve("out/runs/1-home/" + ProcessRuns.OUTPUT)));
            assertTrue(Files.exists(dir.resolve("out/runs/2-home/" + ProcessRuns.OUTPUT)));
            assertTrue(Files.exists(dir.resolve("out/runs/3-home/" + ProcessRuns.OUTPUT)));
            assertTrue(sweeps.out().contains("the runs after 1-home went in processes of their own: it left thread"
                    + " \"scheduler\" in " + CatchingDlc.class.getName()), sweeps.out());
            assertTrue(Files.readString(dir.resolve("out/runs/1-home/server.log")).contains(": still running (it caught"
                    + " the stop)\n"));
        } finally {
            Files.delete(flag);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"loader", "process"})
    void aRobotThatCallsSystemExitFailsItsRunAndEndsNoOtherRun(String isolation) throws Exception {
        // In the sweep's own process it would end every run at once: its runs go to processes of their own.
        Path p = properties("maxSimulationTime=30", "dlcName=" + ExitingDlc.class.getName());
        int status = sweep("-p", p.toString(), "--seeds", "1-2", "--jobs", "2", "--isolation", isolation, "--out",
                dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
        assertEquals(3, rows.size(), rows.toString());
        for (String row : rows.subList(1, 3)) {
            assertTrue(row.contains(",2,client failed: called System.exit in " + ExitingDlc.class.getName()
                    + ".quit(ExitingDlc.java:"), row);
        }
        if (isolation.equals("loader")) {
            assertTrue(sweeps.out().contains("each run went in a process of its own: " + ExitingDlc.class.getName()
                    + ".quit calls System.exit, which would end every run in the sweep's process at once"), sweeps.out());
        }
    }

    @Test
    void theWallsOfAMapsImageAreInTheSweepsFingerprintSoAResumeCannotMixTwoWorlds() throws Exception {
        Path yaml = write("m.yaml", "image: m.pgm", "resolution: 0.5", "origin: [0.0, 0.0, 0.0]",
                "occupied_thresh: 0.65", "free_thresh: 0.196", "negate: 0");
        String text = Files.readString(yaml);
        write("m.pgm", "P2", "3 2", "255", "0 255 255", "255 255 255");
        String before = Batch.imagedWalls("m.yaml", text, RsPlanParser.parse(text, yaml.toString()));
        write("m.pgm", "P2", "3 2", "255", "255 255 0", "255 255 255");
        String after = Batch.imagedWalls("m.yaml", text, RsPlanParser.parse(text, yaml.toString()));
        assertTrue(before.startsWith("\0walls "), before);
        assertTrue(!before.equals(after), "the same text, another image");
        String plain = "wall w { geometry: 0, 0, 4, 0, 0.05; }";
        assertEquals("", Batch.imagedWalls("p.txt", plain, RsPlanParser.parse(plain, "p.txt")),
                "a plan without an image is its text alone, as in sweeps begun before");
    }

    @Test
    void aHandlerThatRunsOutOfMemoryFailsItsRobotNotTheSimulation() throws Exception {
        // Called directly, as the robot's own thread over a pipe: status 2 naming the client, not 70.
        Path p = properties("maxSimulationTime=5", "dlcName=" + GreedyDlc.class.getName());
        int status = sweep("-p", p.toString(), "--seeds", "1", "--out", dir.resolve("out").toString());
        assertEquals(Sweep.RUN_FAILED, status, sweeps.out() + sweeps.err());
        String row = Files.readAllLines(dir.resolve("out/results.csv")).get(1);
        assertTrue(row.contains(",2,client failed: client " + GreedyDlc.class.getName() + ": a handler failed:"
                + " java.lang.OutOfMemoryError: Java heap space"), row);
    }

    @Test
    void aRunsFolderIsNamedAfterItsPlanWithoutTheEndingOfAPlanOrAMap() {
        assertEquals("contest", Batch.stem("FloorPlans/contest.txt"));
        assertEquals("rooms", Batch.stem("maps/rooms.yaml"), "a map's plan too");
        assertEquals("lab", Batch.stem("lab.YML"));
        assertEquals("my_plan.v2", Batch.stem("my plan.v2.txt"));
    }

    @Test
    void aSweepIntoAFolderThatHoldsOneOrOtherFilesIsRefusedSoNoResultIsLost() throws Exception {
        Path p = properties("exitWhenClientsDone=true", "maxSimulationTime=30");
        String out = dir.resolve("out").toString();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1-3", "--out", out), sweeps.err());
        sweeps.reset();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--out", out));
        assertEquals("rp1.Sweep: --out " + out + " holds a sweep already (sweep.ini): add --resume to go on with it, or"
                + " give another --out (or delete that one), so that its results are not lost\n", sweeps.err());
        assertEquals(4, Files.readAllLines(dir.resolve("out/results.csv")).size(), "the three rows are still there");
        Files.createDirectories(dir.resolve("mine"));
        Files.writeString(dir.resolve("mine/results.csv"), "my own\n");
        sweeps.reset();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--out", dir.resolve("mine").toString()));
        assertTrue(sweeps.err().contains("is not empty and holds no sweep: give a new or empty folder"), sweeps.err());
        assertEquals("my own\n", Files.readString(dir.resolve("mine/results.csv")));
    }

    @Test
    void aRobotClassThatIsNotThereAndAMissingOptionAreToldBeforeAnyRun() throws Exception {
        Path p = properties("exitWhenClientsDone=true", "maxSimulationTime=30", "dlcName=no.such.Robot");
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1-4", "--out", dir.resolve("out").toString()));
        assertTrue(sweeps.err().contains(p + ": dlcName=no.such.Robot: no such class on the robot's class path (give the"
                + " robot's classes with -cp)"), sweeps.err());
        assertTrue(Files.notExists(dir.resolve("out")), "no run failed one by one");
        sweeps.reset();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1-4"));
        assertTrue(sweeps.err().startsWith("rp1.Sweep: -p, --seeds and --out are required; missing: --out DIR"), sweeps.err());
    }

    @Test
    void seedsAreRangesAndListsEachSeedOnce() {
        assertEquals(List.of(1L, 2L, 3L, 7L), SweepOptions.seeds("1-3,7,2"));
        assertThrows(IllegalArgumentException.class, () -> SweepOptions.seeds("3-1"));
        assertThrows(IllegalArgumentException.class, () -> SweepOptions.seeds("a"));
    }

    /** A limit the command line runs into is said, with the limit. */
    @Test
    void tooManySeedsOrTooLongATimeoutSayWhereTheLimitIs() throws Exception {
        IllegalArgumentException seeds = assertThrows(IllegalArgumentException.class,
                () -> SweepOptions.seeds("1-100000000"));
        assertEquals("--seeds 1-100000000: 1-100000000 is more than 100000 seeds, the most runs a sweep makes",
                seeds.getMessage());
        Path p = properties("exitWhenClientsDone=true");
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--timeout", "1e308", "--out",
                dir.resolve("out").toString()));
        assertTrue(sweeps.err().startsWith("rp1.Sweep: --timeout needs a positive number up to 10000000, got 1e308\n"),
                sweeps.err());
    }

    /** An output folder that cannot be made says why, not only where. */
    @Test
    void anOutputFolderUnderAFileSaysWhyItCannotBeMade() throws Exception {
        Path p = properties("exitWhenClientsDone=true");
        Path file = Files.writeString(dir.resolve("a-file"), "not a folder");
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--out", file.resolve("out").toString()));
        assertTrue(sweeps.err().contains(": a file of that name is in the way") || sweeps.err().contains(": Not a directory"),
                sweeps.err());
    }
}
