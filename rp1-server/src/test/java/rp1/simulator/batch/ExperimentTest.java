package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.TreeMap;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Sweep;

/**
 * Sweeps over parameters: the grid of varied keys, seeds and plans, the robot's parameters, seed and
 * results in the table, the same row for a run whatever else runs beside it, and runs in processes
 * of their own giving the same rows.
 */
@Timeout(120)
class ExperimentTest {
    @TempDir
    Path dir;
    private final InProcessSweep sweeps = new InProcessSweep();

    private int sweep(String... args) {
        return sweeps.run(args);
    }

    private Path properties(String... extra) throws IOException {
        Files.write(dir.resolve("home.txt"), List.of("caption: \"open\";", "wall w { geometry: 0, 0, 6, 0, 0.05; }",
                "wall v { geometry: 0, 4, 6, 4, 0.05; }", "placement home { geometry: 1, 1, 0, 0.2; }"));
        List<String> lines = new ArrayList<>(List.of("floorPlanFileName=" + dir.resolve("home.txt"), "enableGUI=false",
                "enableNetworkClients=false", "interlockEnabled=true", "simulationSpeed=max", "dlcEnabled=true",
                "dlcName=" + ExperimentDlc.class.getName(), "exitWhenClientsDone=true", "maxSimulationTime=30"));
        lines.addAll(List.of(extra));
        return Files.write(dir.resolve("experiment.ini"), lines);
    }

    /** ExperimentDlc as a program of its own, for --client. */
    private static String clientProgram() {
        return Path.of(System.getProperty("java.home"), "bin", "java") + " -cp " + System.getProperty("java.class.path")
                + " " + ExperimentDlc.class.getName();
    }

    private List<List<String>> table(String folder, String file) throws IOException {
        return CsvText.rows(Files.readString(dir.resolve(folder).resolve(file)));
    }

    /** The rows by (speed, seed), without the columns that may differ between sweeps: run folder and wall time. */
    private static Map<String, List<String>> byRun(List<List<String>> table) {
        List<String> header = table.get(0);
        Map<String, List<String>> rows = new TreeMap<>();
        for (List<String> row : table.subList(1, table.size())) {
            List<String> kept = new ArrayList<>();
            for (int i = 0; i < header.size(); i++) {
                if (!header.get(i).equals("run") && !header.get(i).equals("wall_seconds")) {
                    kept.add(header.get(i) + "=" + row.get(i));
                }
            }
            rows.put(row.get(header.indexOf("param.speed")) + "/" + row.get(header.indexOf("seed")), kept);
        }
        return rows;
    }

    @Test
    void theSweepIsTheFullProductOfTheVariedKeysSeedsAndPlansAndTheRobotReadsItsParametersAndSeed() throws Exception {
        Path p = properties();
        int status = sweep("-p", p.toString(), "--seeds", "3-4", "--vary", "param.speed=0.1,0.25", "--vary",
                "maxSimulationTime=20:30:10", "--jobs", "2", "--out", dir.resolve("out").toString());
        assertEquals(0, status, sweeps.out() + sweeps.err());
        List<List<String>> t = table("out", "results.csv");
        assertEquals(List.of("param.speed", "maxSimulationTime", "seed", "plan", "run", "robot", "start_x", "start_y",
                "start_heading", "end_x", "end_y", "end_heading", "end_time", "distance", "collisions",
                "first_collision_time", "events", "result.speed", "result.seed", "result.made", "status", "reason",
                "wall_seconds"), t.get(0));
        assertEquals(9, t.size(), t.toString());
        List<String> grid = new ArrayList<>();
        for (List<String> row : t.subList(1, 9)) {
            grid.add(row.get(0) + " " + row.get(1) + " " + row.get(2) + " " + row.get(4));
            assertEquals("Experimenter", row.get(5));
            assertEquals(row.get(0), row.get(17), "the robot read its speed");
            assertEquals(row.get(2), row.get(18), "the robot read the run's seed");
            assertEquals("1", row.get(19), "each run has its own copy of the robot's classes");
            assertEquals(List.of("1", "1", "0"), row.subList(6, 9), "start pose");
            double speed = Double.parseDouble(row.get(0));
            assertEquals(Numbers.format(1 + 2 * speed, Numbers.MODEL), row.get(9), "end_x");
            assertEquals(Numbers.format(2 * speed, Numbers.MODEL), row.get(13), "distance");
            assertEquals("clients-done", row.get(21));
        }
        assertEquals(List.of("0.1 20 3 runs/c1-3-home", "0.1 20 4 runs/c1-4-home", "0.1 30 3 runs/c2-3-home",
                "0.1 30 4 runs/c2-4-home", "0.25 20 3 runs/c3-3-home", "0.25 20 4 runs/c3-4-home",
                "0.25 30 3 runs/c4-3-home", "0.25 30 4 runs/c4-4-home"), grid);
        assertTrue(Files.readString(dir.resolve("out/runs/c3-4-home/run.ini")).contains("\nparam.speed=0.25\n"));

        List<List<String>> summary = table("out", "summary.csv");
        assertEquals(5, summary.size(), summary.toString());
        List<String> h = summary.get(0);
        assertEquals(List.of("param.speed", "maxSimulationTime", "plan", "robot", "runs", "failed"), h.subList(0, 6));
        assertEquals("0.5", summary.get(3).get(h.indexOf("distance_mean")));
        assertEquals("2", summary.get(3).get(h.indexOf("distance_n")));
        assertEquals("0", summary.get(3).get(h.indexOf("distance_sd")));
        assertTrue(Files.readString(dir.resolve("out/results.md")).contains("| `distance` | m |"));
        assertTrue(Files.size(dir.resolve("out/summary.png")) > 0);
    }

    @Test
    void aRunGivesTheSameRowAloneInABatchFirstOrLastAndInAProcessOfItsOwn() throws Exception {
        Path p = properties("param.place=$random");
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1-4", "--vary", "param.speed=0.1,0.3", "--jobs", "2",
                "--out", dir.resolve("batch").toString()), sweeps.err());
        Map<String, List<String>> batch = byRun(table("batch", "results.csv"));
        assertEquals(8, batch.size());
        assertEquals(2, batch.values().stream().map(r -> r.get(6)).distinct().limit(2).count(),
                "the seed decides where the robot starts");

        assertEquals(0, sweep("-p", p.toString(), "--seeds", "4,2,3,1", "--vary", "param.speed=0.3,0.1", "--jobs", "1",
                "--out", dir.resolve("shuffled").toString()), sweeps.err());
        assertEquals(batch, byRun(table("shuffled", "results.csv")), "the same rows in another order of runs");

        assertEquals(0, sweep("-p", p.toString(), "--seeds", "3", "--vary", "param.speed=0.1", "--out",
                dir.resolve("alone").toString()), sweeps.err());
        assertEquals(Map.of("0.1/3", batch.get("0.1/3")), byRun(table("alone", "results.csv")));

        assertEquals(0, sweep("-p", p.toString(), "--seeds", "2,3", "--vary", "param.speed=0.3", "--isolation",
                "process", "--jobs", "2", "--out", dir.resolve("process").toString()), sweeps.err());
        assertEquals(Map.of("0.3/2", batch.get("0.3/2"), "0.3/3", batch.get("0.3/3")),
                byRun(table("process", "results.csv")), "a process of its own gives the same rows");
    }

    /**
     * A varied parameter that the robot never asks for is told, in a process of its own as in the
     * sweep's: its configurations are the same robot, and a mistyped name is the likely cause.
     */
    @Test
    void aVariedParameterNoRobotAsksForIsTold() throws Exception {
        Path p = properties();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.sped=0.1,0.3", "--vary",
                "param.speed=0.1,0.2", "--out", dir.resolve("typo").toString()), sweeps.err());
        assertEquals("rp1.Sweep: --vary param.sped: no robot asked for it (RsClient.getRunParameter(\"sped\")), so its"
                + " configurations differ by its name alone; did you mean param.speed (the robot asked for it)?\n", sweeps.err());
        sweeps.reset();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.sped=0.1", "--isolation", "process",
                "--out", dir.resolve("process").toString()), sweeps.err());
        assertTrue(sweeps.err().contains("--vary param.sped: no robot asked for it"), sweeps.err());
        sweeps.reset();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.speed=0.1,0.2", "--out",
                dir.resolve("read").toString()), sweeps.err());
        assertEquals("", sweeps.err(), "the robot asks for speed");
    }

    @Test
    void theContinuityCounterOf060StartsAgainInEveryRun() throws Exception {
        // RsMotion.getNewContinuityID() was one counter for the process: seeds 1 to 4 run one after
        // another read 1, 2, 3 and 4, and seed 3 alone read 1.
        Path p = properties("dlcName=" + NumberingDlc.class.getName());
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1-4", "--jobs", "1", "--out", dir.resolve("out").toString()),
                sweeps.err());
        List<List<String>> rows = table("out", "results.csv");
        int first = rows.get(0).indexOf("result.first");
        for (List<String> row : rows.subList(1, rows.size())) {
            assertEquals("1", row.get(first), row.toString());
        }
    }

    @Test
    void resumeRefusesAnotherGrid() throws Exception {
        Path p = properties();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.speed=0.1", "--out",
                dir.resolve("out").toString()), sweeps.err());
        sweeps.reset();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.speed=0.1,0.2", "--out",
                dir.resolve("out").toString(), "--resume"));
        assertTrue(sweeps.err().contains("the varied keys (--vary): param.speed=0.1 there,"
                + " param.speed=0.1,0.2 here"), sweeps.err());
    }

    @Test
    void resumeOfASweepAnEarlierVersionBeganSaysItCannotGoOn() throws Exception {
        Path p = properties();
        String[] args = {"-p", p.toString(), "--seeds", "1", "--out", dir.resolve("out").toString()};
        assertEquals(0, sweep(args), sweeps.err());
        Path spec = dir.resolve("out").resolve(SweepSpec.FILE);
        Files.writeString(spec, Files.readString(spec).replace("rp1-sweep=3", "rp1-sweep=2"));
        sweeps.reset();
        String[] resume = Arrays.copyOf(args, args.length + 1);
        resume[args.length] = "--resume";
        assertEquals(1, sweep(resume));
        assertTrue(sweeps.err().contains("the format of sweep.ini: 2 there, 3 here. An earlier version of RP1 began it"
                + " and this one cannot go on with it: give another --out"), sweeps.err());
    }

    @Test
    void resumeRefusesARobotThatChangedSince() throws Exception {
        // Rows of two versions of a robot averaged together would answer no question.
        Path p = properties();
        Path robot = Files.writeString(dir.resolve("robot.sh"), "exit 0\n");
        String[] args = {"-p", p.toString(), "--seeds", "1-2", "--client", "sh " + robot, "--out", dir.resolve("out").toString()};
        sweep(args);
        sweeps.reset();
        Files.writeString(robot, "exit 0 # now better\n");
        String[] resume = Arrays.copyOf(args, args.length + 1);
        resume[args.length] = "--resume";
        assertEquals(1, sweep(resume));
        assertTrue(sweeps.err().contains("the robot's code (its classes, or the files the --client command names) is"
                + " not the same"), sweeps.err());
    }

    @Test
    void variedValuesThatMakeBadPropertiesAreRefusedBeforeAnythingRuns() throws Exception {
        Path p = properties();
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--vary", "maxSimulationTime=10,soon", "--out",
                dir.resolve("out").toString()));
        assertTrue(sweeps.err().contains("maxSimulationTime=soon: a number expected (with"
                + " --vary maxSimulationTime=soon)"), sweeps.err());
        assertTrue(Files.notExists(dir.resolve("out")));
    }

    @Test
    void aClientProgramIsEachRunsRobotWithTheRunInItsEnvironment() throws Exception {
        Path p = properties();
        String java = clientProgram();
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "8", "--vary", "param.speed=0.15", "--client", java,
                "--out", dir.resolve("out").toString()), sweeps.err());
        List<String> header = table("out", "results.csv").get(0);
        List<String> row = table("out", "results.csv").get(1);
        assertEquals("0.15", row.get(header.indexOf("result.speed")));
        assertEquals("8", row.get(header.indexOf("result.seed")));
        assertEquals("0.3", row.get(header.indexOf("distance")));
        assertEquals("nobody-left", row.get(header.indexOf("reason")));
        assertFalse(sweeps.out().contains("robot's classes"), "no classes of a robot were loaded: " + sweeps.out());
    }

    @Test
    void aClientProgramThatEndsWithAnErrorFailsItsRun() throws Exception {
        // Its robot leaves the floor, which ends the run (nobody-left), and then the program fails: an
        // exit status the run must not read as success.
        Path p = properties();
        String java = clientProgram();
        assertEquals(Sweep.RUN_FAILED, sweep("-p", p.toString(), "--seeds", "8", "--vary", "param.exit=0,3", "--client",
                java, "--out", dir.resolve("out").toString()), sweeps.err());
        List<String> header = table("out", "results.csv").get(0);
        List<String> ok = table("out", "results.csv").get(1);
        List<String> failed = table("out", "results.csv").get(2);
        assertEquals(List.of("0", "0", "nobody-left"), List.of(ok.get(header.indexOf("param.exit")),
                ok.get(header.indexOf("status")), ok.get(header.indexOf("reason"))));
        assertEquals(List.of("3", "2"), List.of(failed.get(header.indexOf("param.exit")), failed.get(header.indexOf("status"))));
        assertTrue(failed.get(header.indexOf("reason")).startsWith("client failed: the program ended with status 3"),
                failed.toString());
        assertEquals("0.4", failed.get(header.indexOf("distance")), "the robot's row is still there");
    }

    @Test
    void aVariedValueReachesTheRobotAsWrittenBackslashesAndAll() throws Exception {
        // run.ini is a properties file: unescaped, a\b reached the robot as ab and \u0041BC as ABC.
        Path p = properties("param.place=home");
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.note=a\\b,\\u0041BC", "--out",
                dir.resolve("out").toString()), sweeps.err());
        for (String[] run : new String[][] {{"c1-1-home", "a\\b"}, {"c2-1-home", "\\u0041BC"}}) {
            Properties read = new Properties();
            try (Reader in = Files.newBufferedReader(dir.resolve("out/runs").resolve(run[0]).resolve(SweepRun.PROPERTIES))) {
                read.load(in);
            }
            assertEquals(run[1], read.getProperty("param.note"));
            assertEquals(dir.resolve("home.txt").toString(), read.getProperty("floorPlanFileName"));
        }
    }

    @Test
    void twoParametersThatAClientProgramWouldReadFromOneVariableAreRefused() throws Exception {
        Path p = properties("param.a-b=1");
        assertEquals(1, sweep("-p", p.toString(), "--seeds", "1", "--vary", "param.a_b=2", "--client", "true",
                "--out", dir.resolve("out").toString()));
        assertTrue(sweeps.err().contains("param.a-b and param.a_b would both reach the --client program as"
                + " RP1_PARAM_a_b: rename one"), sweeps.err());
    }

    @Test
    void aClientProgramThatEndsWithoutARobotFailsItsRunInsteadOfHangingIt() throws Exception {
        Path p = properties();
        assertEquals(Sweep.RUN_FAILED, sweep("-p", p.toString(), "--seeds", "1", "--client", "false", "--out",
                dir.resolve("out").toString()), sweeps.err());
        List<String> row = table("out", "results.csv").get(1);
        assertEquals(List.of("2", "client failed: the program ended with status 1 before the run did: it printed nothing"),
                row.subList(row.size() - 3, row.size() - 1));
    }

    @Test
    void theEndPoseAndDistanceAreThoseAtTheEndTimeNotAtTheLastModellingFrame() throws Exception {
        // The robot drives at 0.1 m/s from x = 1 for two seconds; the run ends at 1.03 s, between frames.
        Path p = properties("maxSimulationTime=1.03", "param.speed=0.1");
        assertEquals(0, sweep("-p", p.toString(), "--seeds", "1", "--out", dir.resolve("out").toString()), sweeps.err());
        List<String> header = table("out", "results.csv").get(0);
        List<String> row = table("out", "results.csv").get(1);
        assertEquals("1.03", row.get(header.indexOf("end_time")));
        assertEquals("1.103", row.get(header.indexOf("end_x")));
        assertEquals("0.103", row.get(header.indexOf("distance")));
        assertEquals("max-simulation-time", row.get(header.indexOf("reason")));
    }
}
