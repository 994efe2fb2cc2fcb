package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;

/**
 * A run stopped while a robot's handler never returns: its recording, written under its own name,
 * must replay. Its end counted the tasks that finished but the events of the one still running, so
 * the replay said it differed from the recorded run (exit status 3), and that is the run a user most
 * wants to look at.
 */
@Timeout(60)
class HandlerThatNeverReturnsTest {
    @TempDir
    Path dir;

    @Test
    void theRecordingOfARunStoppedInAHandlerThatNeverReturnedReplays() throws Exception {
        HangingDlc.release = new CountDownLatch(1);
        try {
            RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcSetIO=true", "dlcName="
                    + HangingDlc.class.getName(), "simulationSpeed=max", "interlockEnabled=true",
                    "enableNetworkClients=false", "maxSimulationTime=10", "recordFileName=run.rec",
                    "eventLogFileName=events.txt");
            Thread.sleep(500);
            server.stop();
        } finally {
            HangingDlc.release.countDown();
        }
        assertTrue(Files.exists(dir.resolve("run.rec")), "written under its own name");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {dir.resolve("run.rec").toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(out, true, StandardCharsets.UTF_8));
        assertEquals(0, status, out.toString(StandardCharsets.UTF_8));
    }
}
