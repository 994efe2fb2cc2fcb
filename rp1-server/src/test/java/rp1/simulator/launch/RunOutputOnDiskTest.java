package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import rp1.Replay;

/**
 * What a run leaves on disk when it does not end well: killed with SIGKILL, the last wall-clock
 * second at most is missing and the replay says the recording is partial; a full disk or a picture
 * that cannot be written gives an exit status of its own, and nothing half-written under a file's name.
 */
@Timeout(60)
class RunOutputOnDiskTest {
    private static final Path DEV_FULL = Paths.get("/dev/full");

    @TempDir
    Path dir;

    @Test
    void aServerKilledWithSigkillLeavesARecordingThatReplaysAsPartial() throws Exception {
        TestServer.write(dir, "enableNetworkClients=false", "simulationSpeed=1", "dlcEnabled=true",
                "dlcName=" + TirelessDlc.class.getName(), "recordFileName=run.rec", "eventLogFileName=run.events");
        Process server = new ProcessBuilder(JavaCommand.of(List.of(), "rp1.Server", "-p", TestServer.PROPERTIES))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
        try {
            for (int i = 0; i < 200 && Files.notExists(dir.resolve(TestServer.LOG)); i++) {
                Thread.sleep(50);
            }
            TestServer.awaitLog(dir, "Starting main scheduler loop");
            // Heartbeats every 0.1 s of a paced run: well over a second's worth is on disk after 2.5 s.
            Thread.sleep(2500);
        } finally {
            server.destroyForcibly();
            assertTrue(server.waitFor(10, TimeUnit.SECONDS), "the server was killed");
        }

        assertFalse(Files.exists(dir.resolve("run.rec")), "a recording that was not finished is not under its name");
        String events = Files.readString(dir.resolve("run.events.part"));
        assertTrue(events.startsWith("# rp1-events 1\n"), events);
        assertTrue(events.contains(" Heartbeat sequence=10"), "a second of events is on disk:\n" + events);

        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Path part = dir.resolve("run.rec.part");
        int status = Replay.run(new String[] {part.toString()}, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(Replay.PARTIAL, status, out.toString() + err);
        String said = err.toString(StandardCharsets.UTF_8);
        assertTrue(said.startsWith("rp1.Replay: partial recording: " + part + " ends at t=")
                && said.contains(" s (it has no end line: the run did not stop cleanly)"), said);

        err.reset();
        assertEquals(1, Replay.run(new String[] {dir.resolve("run.rec").toString()}, new PrintStream(out),
                new PrintStream(err, true, StandardCharsets.UTF_8)));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("run.rec does not exist, but " + part + " does: the run"
                + " did not stop cleanly"), err.toString());
    }

    @ParameterizedTest
    @CsvSource({"recordFileName, cannot finish the recording", "eventLogFileName, cannot finish the event log"})
    void aFileThatCannotBeFinishedOnAFullDiskGivesItsOwnExitStatus(String key, String message) throws Exception {
        assumeTrue(Files.isWritable(DEV_FULL), "writing to /dev/full fails with ENOSPC (Linux)");
        Files.createSymbolicLink(dir.resolve("run.out.part"), DEV_FULL);
        RunningServer server = TestServer.start(dir, "enableNetworkClients=false", "simulationSpeed=max",
                "interlockEnabled=true", "dlcEnabled=true", "dlcName=" + TestDlc.class.getName(),
                "exitWhenClientsDone=true", key + "=run.out");

        assertEquals(ExitStatus.OUTPUT_FAILED, server.awaitExit());
        assertTrue(TestServer.log(dir).contains("The run's output is not whole: " + message + " " + dir.resolve("run.out")
                + ": No space left on device"), TestServer.log(dir));
        assertFalse(Files.exists(dir.resolve("run.out")), "nothing half-written under the file's name");
    }

    @Test
    void aPictureThatCannotBeWrittenLeavesNoPartFileAndGivesItsOwnExitStatus() throws Exception {
        // A folder, not empty, under the picture's name: the finished picture cannot take its place.
        Files.createDirectories(dir.resolve("end.png/in-the-way"));
        RunningServer server = TestServer.start(dir, "enableNetworkClients=false", "simulationSpeed=max", "interlockEnabled=true",
                "dlcEnabled=true", "dlcName=" + TestDlc.class.getName(), "exitWhenClientsDone=true",
                "snapshotFileName=" + dir.resolve("end.png"));

        assertEquals(ExitStatus.OUTPUT_FAILED, server.awaitExit());
        assertTrue(TestServer.log(dir).contains("The run's output is not whole: cannot write the picture "
                + dir.resolve("end.png")), TestServer.log(dir));
        assertFalse(Files.exists(dir.resolve("end.png.part")), "no half-written picture left behind");
    }

    /** A recording or event log named after a folder is refused, and the folder is left as it was. */
    @Test
    void aRecordingOrEventLogNamedAfterAFolderIsRefusedAndTheFolderKept() throws Exception {
        Files.createDirectories(dir.resolve("empty"));
        Files.createDirectories(dir.resolve("full/inside"));
        for (String setting : List.of("recordFileName=empty", "recordFileName=full", "eventLogFileName=empty")) {
            StartupException e = assertThrows(StartupException.class, () -> TestServer.start(dir,
                    "enableNetworkClients=false", "simulationSpeed=max", "interlockEnabled=true", "dlcEnabled=true",
                    "dlcName=" + TestDlc.class.getName(), "exitWhenClientsDone=true", setting));
            String name = setting.substring(setting.indexOf('=') + 1);
            assertTrue(e.getMessage().contains(name + " (" + setting.substring(0, setting.indexOf('=')) + "): it is a folder"),
                    e.getMessage());
            assertTrue(Files.isDirectory(dir.resolve(name)), "the folder is still there");
            assertFalse(Files.exists(dir.resolve(name + ".part")), "nothing left beside it");
        }
    }

    @Test
    void aRunWhoseOutputIsWholeStillEndsWithStatusZero() throws Exception {
        RunningServer server = TestServer.start(dir, "enableNetworkClients=false", "simulationSpeed=max", "interlockEnabled=true",
                "dlcEnabled=true", "dlcName=" + TestDlc.class.getName(), "exitWhenClientsDone=true",
                "recordFileName=run.rec", "eventLogFileName=run.events", "snapshotFileName=" + dir.resolve("end.png"));

        assertEquals(ExitStatus.OK, server.awaitExit());
        assertTrue(Files.readString(dir.resolve("run.rec")).contains("\nend "));
        assertFalse(Files.exists(dir.resolve("run.rec.part")));
        assertFalse(Files.exists(dir.resolve("run.events.part")));
        assertFalse(Files.exists(dir.resolve("end.png.part")));
    }
}
