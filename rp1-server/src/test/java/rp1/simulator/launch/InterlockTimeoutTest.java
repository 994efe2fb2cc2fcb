package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A network client that stops answering holds simulated time for everyone while the interlock waits
 * for it, as in RP1 0.60; with {@code interlockTimeout} it is disconnected and the world goes on.
 */
@Timeout(30)
class InterlockTimeoutTest {
    @TempDir
    Path dir;

    @Test
    void aClientThatNeverAcknowledgesIsDisconnectedAfterTheInterlockTimeoutAndTheRunGoesOn() throws Exception {
        // The loaded robot keeps time moving (its handlers are called directly: no interlock of its own),
        // a few thousand simulated seconds a wall second: the run is long enough in simulated time that
        // the silent client's request, sent once it has connected, falls well before its end (with 5 s
        // the whole run could pass before the request was read, and then nothing was waited for).
        RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcName=" + TirelessDlc.class.getName(),
                "simulationSpeed=max", "interlockEnabled=true", "maxSimulationTime=2000", "interlockTimeout=1");
        try (RawClient silent = RawClient.connected(server.getPort())) {
            silent.sendTimeout(0.5, 1); // its event at 0.5 s is never acknowledged
            assertEquals(OptionalInt.of(ExitStatus.OK), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
        } finally {
            server.stop();
        }
        String log = TestServer.log(dir);
        assertTrue(log.contains("closing the connection: it did not acknowledge an event within 1.0 s (interlockTimeout)"),
                log);
        assertTrue(log.contains("maxSimulationTime 2000.0 s reached"), log);
    }
}
