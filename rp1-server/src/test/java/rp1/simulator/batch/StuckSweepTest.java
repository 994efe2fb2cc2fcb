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
 * A sweep whose job never comes back (its thread lost in the JDK's code when a robot filled the heap
 * of the sweep's process) does not wait for it for ever: once no run has started or ended for longer
 * than a run can take, the sweep stops with a line that says so, and keeps the runs that finished for
 * --resume.
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

    private static int sweep(ByteArrayOutputStream said, RunEngine.Factory engines, String... args) {
        PrintStream to = new PrintStream(said, true, StandardCharsets.UTF_8);
        return Sweep.run(args, to, to, false, new Interruption(), engines);
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
            while (run.seed() == lostSeed && never.getCount() > 0) {
                try {
                    never.await();
                } catch (InterruptedException e) {
                    // As a thread lost in the JDK's code: it hears nothing.
                }
            }
            return engine.run(run);
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
