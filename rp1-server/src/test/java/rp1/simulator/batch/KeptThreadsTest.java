package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The threads a sweep keeps for its servers' client starters and stops: a task runs under its own
 * name and with the context class loader of the thread that started it, a kept thread serves the next
 * task, and a robot started from one sees its own run's classes.
 */
class KeptThreadsTest {
    @TempDir
    Path dir;

    private record Seen(Thread thread, String name, ClassLoader context, boolean interrupted) {
    }

    private static Seen runOn(KeptThreads threads, String name, boolean interruptItself) throws Exception {
        CompletableFuture<Seen> seen = new CompletableFuture<>();
        threads.start(name, true, () -> {
            Thread t = Thread.currentThread();
            seen.complete(new Seen(t, t.getName(), t.getContextClassLoader(), t.isInterrupted()));
            if (interruptItself) {
                t.interrupt();
            }
        });
        return seen.get(10, TimeUnit.SECONDS);
    }

    @Test
    void aTaskRunsUnderItsNameWithItsStartersContextLoaderOnAKeptThread() throws Exception {
        Thread me = Thread.currentThread();
        ClassLoader before = me.getContextClassLoader();
        try (KeptThreads threads = new KeptThreads();
             URLClassLoader runA = new URLClassLoader(new URL[0], before);
             URLClassLoader runB = new URLClassLoader(new URL[0], before)) {
            me.setContextClassLoader(runA);
            Seen first = runOn(threads, "dlc start", true);
            assertEquals("dlc start", first.name());
            assertSame(runA, first.context());
            // The first task is over: the next one finds its thread idle, named as such, with nothing left of it.
            for (int wait = 0; wait < 200 && !first.thread().getName().startsWith("rp1-run-helper"); wait++) {
                Thread.sleep(5);
            }
            assertTrue(first.thread().getName().startsWith("rp1-run-helper"), first.thread().getName());
            assertNotEquals(runA, first.thread().getContextClassLoader());
            me.setContextClassLoader(runB);
            Seen second = runOn(threads, "shutdown", false);
            assertSame(first.thread(), second.thread(), "the thread was kept");
            assertEquals("shutdown", second.name());
            assertSame(runB, second.context());
            assertFalse(second.interrupted(), "the first task's interrupt stayed with it");
        } finally {
            me.setContextClassLoader(before);
        }
    }

    @Test
    void aTaskStartedAfterTheSweepEndedStillRuns() throws Exception {
        KeptThreads threads = new KeptThreads();
        threads.close();
        Seen late = runOn(threads, "shutdown", false);
        assertEquals("shutdown", late.name());
    }

    @Test
    void aRobotStartedFromAKeptThreadSeesItsOwnRunsClasses() throws IOException {
        Path p = HomeSweep.properties(dir, "context", ContextDlc.class);
        InProcessSweep sweeps = new InProcessSweep();
        assertEquals(0, sweeps.run("-p", p.toString(), "--seeds", "1-6", "--jobs", "2", "--out",
                dir.resolve("out").toString()), sweeps.out() + sweeps.err());
        List<List<String>> rows = CsvText.rows(Files.readString(dir.resolve("out/results.csv")));
        int column = rows.get(0).indexOf("result.own_context");
        assertEquals(7, rows.size(), rows.toString());
        for (List<String> row : rows.subList(1, rows.size())) {
            assertEquals("1", row.get(column), row.toString());
        }
    }
}
