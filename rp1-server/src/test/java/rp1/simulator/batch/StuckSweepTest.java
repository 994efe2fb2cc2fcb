package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Sweep;

/**
 * When a robot fills the heap of the sweep's process, a job may fail for want of memory, or its thread
 * may be lost in the JDK's code and never come back. Neither stops the sweep's other runs for good nor
 * makes it wait for ever: a job that failed is a row that says so, and once no run has started or
 * ended for longer than a run can take, the sweep stops with a line that says so. Either way the runs
 * that finished are kept, and --resume carries out the others.
 */
@Timeout(120)
class StuckSweepTest {
    @TempDir
    Path dir;

    @Test
    void aJobThatNeverComesBackEndsTheSweepWithTheRunsThatFinishedKept() throws Exception {
        Path properties = HomeSweep.properties(dir, "experiment", ExperimentDlc.class);
        String out = dir.resolve("out").toString();
        CountDownLatch never = new CountDownLatch(1);
        RunEngine.Factory stuckAtSeed3 = batch -> {
            batch.stuckAfter(5);
            return new Lost(RunEngine.inThisProcess(List.of(ExperimentDlc.class.getName()),
                    StuckSweepTest.class.getClassLoader(), 60), 3, never);
        };
        try {
            ByteArrayOutputStream said = new ByteArrayOutputStream();
            long start = System.nanoTime();
            int status = sweep(said, stuckAtSeed3, "-p", properties.toString(), "--seeds", "1-4", "--jobs", "2",
                    "--out", out);
            String printed = said.toString(StandardCharsets.UTF_8);
            assertEquals(1, status, printed);
            assertTrue(printed.contains("no run started or ended for 5 s, longer than a run can take"), printed);
            assertTrue(printed.contains("add --resume to the same command to carry out the others"), printed);
            assertTrue(System.nanoTime() - start < 60e9, "ended long before the test's timeout");
            List<String> rows = Files.readAllLines(dir.resolve("out/results.csv"));
            assertEquals(4, rows.size(), "the three runs that finished are kept: " + rows);

            ByteArrayOutputStream resumed = new ByteArrayOutputStream();
            assertEquals(0, sweep(resumed, null, "-p", properties.toString(), "--seeds", "1-4", "--jobs", "2",
                    "--out", out, "--resume"), resumed.toString(StandardCharsets.UTF_8));
            assertTrue(resumed.toString(StandardCharsets.UTF_8).contains("3 finished before, 1 to run"),
                    resumed.toString(StandardCharsets.UTF_8));
        } finally {
            never.countDown();
        }
    }

    @Test
    void aJobThatRanOutOfMemoryIsARowThatResumeRunsAgain() throws Exception {
        Path properties = HomeSweep.properties(dir, "experiment", ExperimentDlc.class);
        String out = dir.resolve("out").toString();
        RunEngine.Factory shortAtSeed3 = batch -> new Short(RunEngine.inThisProcess(List.of(ExperimentDlc.class.getName()),
                StuckSweepTest.class.getClassLoader(), 60), 3);
        ByteArrayOutputStream said = new ByteArrayOutputStream();
        int status = sweep(said, shortAtSeed3, "-p", properties.toString(), "--seeds", "1-4", "--jobs", "2", "--out", out);
        String printed = said.toString(StandardCharsets.UTF_8);
        assertEquals(Sweep.RUN_FAILED, status, printed);
        assertTrue(printed.contains("3 runs ended as asked, 1 failed"), "the runs after it went on: " + printed);
        assertTrue(printed.contains("was never carried out") && printed.contains("add --resume"), printed);
        String row = Files.readAllLines(dir.resolve("out/results.csv")).stream().filter(r -> r.startsWith("3,"))
                .findFirst().orElseThrow();
        assertTrue(row.contains("the run could not be started: the sweep's process ran out of memory"
                + " (java.lang.OutOfMemoryError: made up by the test)"), row);

        ByteArrayOutputStream resumed = new ByteArrayOutputStream();
        assertEquals(0, sweep(resumed, null, "-p", properties.toString(), "--seeds", "1-4", "--jobs", "2", "--out", out,
                "--resume"), resumed.toString(StandardCharsets.UTF_8));
        assertTrue(resumed.toString(StandardCharsets.UTF_8).contains("3 finished before, 1 to run"),
                resumed.toString(StandardCharsets.UTF_8));
    }

    private static int sweep(ByteArrayOutputStream said, RunEngine.Factory engines, String... args) {
        PrintStream to = new PrintStream(said, true, StandardCharsets.UTF_8);
        return Sweep.run(args, to, to, false, new Interruption(), engines);
    }

    /** Carries out runs with another engine, except that the job of one seed runs out of memory. */
    private static final class Short implements RunEngine {
        private final RunEngine engine;
        private final long shortSeed;

        Short(RunEngine engine, long shortSeed) {
            this.engine = engine;
            this.shortSeed = shortSeed;
        }

        @Override
        public Ran run(Batch.Run run) throws IOException, InterruptedException {
            if (run.seed() == shortSeed) {
                throw new OutOfMemoryError("made up by the test");
            }
            return engine.run(run);
        }

        @Override
        public void stopAll() {
            engine.stopAll();
        }

        @Override
        public void close() {
            engine.close();
        }
    }

    /** Carries out runs with another engine, except that the run of one seed never comes back, whatever it is told. */
    private static final class Lost implements RunEngine {
        private final RunEngine engine;
        private final long lostSeed;
        private final CountDownLatch never;

        Lost(RunEngine engine, long lostSeed, CountDownLatch never) {
            this.engine = engine;
            this.lostSeed = lostSeed;
            this.never = never;
        }

        @Override
        public Ran run(Batch.Run run) throws IOException, InterruptedException {
            if (run.seed() != lostSeed) {
                return engine.run(run);
            }
            while (never.getCount() > 0) {
                try {
                    never.await();
                } catch (InterruptedException e) {
                    // As a thread lost in the JDK's code: it hears nothing.
                }
            }
            // Released as the test ends: running now would write into the folder being deleted.
            throw new IOException("released by the test after the sweep ended");
        }

        @Override
        public void stopAll() {
            engine.stopAll();
        }

        @Override
        public boolean runsEndWithinTheirTimeout() {
            return true;
        }

        @Override
        public void close() {
            engine.close();
        }
    }
}
