package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A thread a robot starts and leaves running (from {@code initialize()} or from a handler) is ended
 * with its run in a sweep's process, and the run's log says where it was, so that it does not run on
 * through every later run; the run's group of robots' threads goes with it.
 */
@Timeout(120)
class RobotThreadsTest {
    @TempDir
    Path dir;

    @Test
    void aThreadTheRobotLeftRunningIsEndedWithItsRunAndLogged() throws Exception {
        ThreadGroup here = Thread.currentThread().getThreadGroup();
        int groupsBefore = here.activeGroupCount();
        sweepLeaving(LeakyDlc.class, "leaky helper");
        // Each run's group of robots' threads is let go with the run: a sweep of thousands keeps none.
        assertTrue(here.activeGroupCount() <= groupsBefore, here.activeGroupCount() + " groups, " + groupsBefore + " before");
    }

    @Test
    void aThreadAHandlerStartedAndLeftRunningIsEndedWithItsRunToo() throws Exception {
        // The handler runs on the simulation's thread, which is among the robots' threads for this reason.
        sweepLeaving(LeakyHandlerDlc.class, "leaky handler's helper");
    }

    /**
     * Sweeps two runs of {@code robot}, which leaves a thread named {@code thread} running LeakyDlc.spin:
     * each run's log says it was ended, and it is.
     */
    private void sweepLeaving(Class<?> robot, String thread) throws Exception {
        Path p = HomeSweep.properties(dir, "leaky", robot);
        InProcessSweep sweeps = new InProcessSweep();
        assertEquals(0, sweeps.run("-p", p.toString(), "--seeds", "1-2", "--jobs", "1", "--out",
                dir.resolve("out").toString()), sweeps.out() + sweeps.err());
        for (String run : List.of("1-home", "2-home")) {
            String log = Files.readString(dir.resolve("out/runs").resolve(run).resolve("server.log"));
            assertTrue(log.contains("A thread a loaded client started did not end with the run: thread \"" + thread + "\" in "
                    + LeakyDlc.class.getName() + ".spin"), log);
            assertTrue(log.contains("stopped"), log);
            assertFalse(log.contains("thread \"scheduler\""), "the simulation's own thread is not taken for a robot's: " + log);
        }
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            assertFalse(t.getName().equals(thread) && t.isAlive(), "a robot's thread still runs: " + t);
        }
    }
}
