package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A stop that could not get a thread (the process out of memory or of threads just then) is not taken
 * for a stop under way: the next request stops the server, instead of waiting for ever for a stop
 * that never began (a sweep's run then never ended). Nor does a stop whose thread never runs it, a
 * stop that fails half way, or a simulation that fails with no thread to stop it on, leave whoever
 * waits for the run waiting: in a sweep's process whose heap a robot filled, each of these hung the
 * sweep.
 */
@Timeout(60)
class StopWithoutAThreadTest {
    @TempDir
    Path dir;

    @Test
    void aStopThatCouldNotStartIsTriedAgainByTheNextRequest() throws Exception {
        TestServer.write(dir, "simulationSpeed=1", "waitForClients=0");
        AtomicBoolean refused = new AtomicBoolean();
        HelperThreads threads = HelperThreads.newThreads();
        HelperThreads failingOnce = (name, daemon, task) -> {
            if (name.equals("shutdown") && refused.compareAndSet(false, true)) {
                throw new OutOfMemoryError("unable to create native thread: possibly out of memory");
            }
            threads.start(name, daemon, task);
        };
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                LaunchOptions.defaults().withPort(0).withHelperThreads(failingOnce));
        assertThrows(OutOfMemoryError.class, () -> server.requestStop(ExitStatus.OK));
        assertEquals("running", server.getStopReason());
        assertTrue(server.awaitExit(200, TimeUnit.MILLISECONDS).isEmpty(), "nothing stopped it yet");
        assertEquals(ExitStatus.OK, server.stop());
        assertEquals("stopped", server.getStopReason());
    }

    @Test
    void aStopHandedToAThreadThatNeverRunsItIsDoneByTheCallerOfStop() throws Exception {
        TestServer.write(dir, "simulationSpeed=1", "waitForClients=0");
        HelperThreads threads = HelperThreads.newThreads();
        // As a kept thread that takes the stop and dies before it begins it (out of memory).
        HelperThreads losingTheStop = (name, daemon, task) -> {
            if (!name.equals("shutdown")) {
                threads.start(name, daemon, task);
            }
        };
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                LaunchOptions.defaults().withPort(0).withHelperThreads(losingTheStop));
        server.requestStop(ExitStatus.OK);
        assertTrue(server.awaitExit(200, TimeUnit.MILLISECONDS).isEmpty(), "the stop was lost");
        assertEquals(ExitStatus.OK, server.stop());
        assertEquals("stopped", server.getStopReason());
        assertTrue(TestServer.log(dir).contains("Shutting down simulator"), TestServer.log(dir));
    }

    @Test
    void aStopThatFailsHalfWayStillEndsTheRunAndSaysSo() throws Exception {
        TestServer.write(dir, "enableGUI=true", "simulationSpeed=1", "waitForClients=0");
        ViewHook failingToClose = context -> () -> {
            throw new OutOfMemoryError("made up by the test");
        };
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                LaunchOptions.defaults().withPort(0).withView(failingToClose));
        assertEquals(ExitStatus.FATAL_ERROR, server.stop(), "not a run that ended as asked");
        assertEquals("stopped; the stop failed: java.lang.OutOfMemoryError: made up by the test", server.getStopReason());
        String log = TestServer.log(dir);
        assertTrue(log.contains("The stop failed in part: java.lang.OutOfMemoryError: made up by the test"), log);
        assertTrue(log.contains("Free  Memory:"), "the steps after the one that failed were taken: " + log);
    }

    @Test
    void aSimulationThatFailsWithNoThreadForItsStopIsStoppedOnItsOwnThread() throws Exception {
        HelperThreads threads = HelperThreads.newThreads();
        HelperThreads noneForAStop = (name, daemon, task) -> {
            if (name.equals("shutdown")) {
                throw new OutOfMemoryError("unable to create native thread: possibly out of memory");
            }
            threads.start(name, daemon, task);
        };
        RecursingDlc.internalError = true;
        try {
            TestServer.write(dir, "dlcEnabled=true", "dlcSetIO=true", "dlcName=" + RecursingDlc.class.getName(),
                    "simulationSpeed=max", "interlockEnabled=true", "maxSimulationTime=2");
            RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                    LaunchOptions.defaults().withPort(0).withHelperThreads(noneForAStop));
            assertEquals(OptionalInt.of(ExitStatus.FATAL_ERROR), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
            assertEquals("the simulation failed: java.lang.InternalError: made up by the test", server.getStopReason());
        } finally {
            RecursingDlc.internalError = false;
        }
    }
}
