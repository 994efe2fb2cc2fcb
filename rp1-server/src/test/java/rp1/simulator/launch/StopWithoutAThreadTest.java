package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A stop that could not get a thread (the process out of memory or of threads just then) is not taken
 * for a stop under way: the next request stops the server, instead of waiting for ever for a stop
 * that never began (a sweep's run then never ended).
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
}
