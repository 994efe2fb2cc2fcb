package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Dynamically loaded clients (behavior.md section 3.4) and the exit conditions of headless runs:
 * exitWhenClientsDone, maxSimulationTime, and failing clients.
 */
@Timeout(30)
class LoadedClientTest {
    private static final String DLC = "dlcName=" + TestDlc.class.getName();
    private static final String HEADLESS_CI = "exitWhenClientsDone=true";
    private static final String LOCKSTEP = "simulationSpeed=max";

    @TempDir
    Path dir;

    @BeforeEach
    void reset() {
        TestDlc.reset();
    }

    private int runToTheEnd(String... lines) throws Exception {
        RunningServer server = TestServer.start(dir, lines);
        OptionalInt status = server.awaitExit(20, TimeUnit.SECONDS);
        if (!status.isPresent()) {
            server.stop();
            throw new AssertionError("the server did not stop by itself:\n" + TestServer.log(dir));
        }
        return status.getAsInt();
    }

    @Test
    void anInProcessClientIsCalledInTheOriginalsOrderAndTheServerExitsWhenItIsDone() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", DLC, "dlcSetIO=true", "dlcSetLog=true", HEADLESS_CI,
                LOCKSTEP, "interlockEnabled=true", "enableNetworkClients=false");
        assertEquals(ExitStatus.OK, status, TestServer.log(dir));
        assertEquals(List.of("constructor", "setInputOutputStreams", "setLogger", "initialize", "run"), TestDlc.CALLS);
        List<Double> beats = TestDlc.BEATS;
        assertEquals(5, beats.size(), "beats: " + beats);
        for (int k = 1; k <= 5; k++) {
            assertEquals(0.1 * k, beats.get(k - 1), 1e-9, "lockstep: the clock started after initialize(), at 0");
        }
        String log = TestServer.log(dir);
        assertTrue(log.matches("(?s).*\ns \\S+ 0000\\.000: TestDlc says hello\n.*"), "dlcSetLog: the client logs into the server log\n" + log);
        assertTrue(log.contains("client 1 (in-process " + TestDlc.class.getName() + ") connected"), log);
        assertTrue(log.contains("Every loaded client has finished"), log);
    }

    @Test
    void aLoadedClientWithoutServerIoConnectsOverTheNetworkToTheActualPort() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", DLC, "dlcSetIO=false", HEADLESS_CI, "simulationSpeed=50");
        assertEquals(ExitStatus.OK, status, TestServer.log(dir));
        assertEquals(List.of("constructor", "setLogger", "initialize", "run"), TestDlc.CALLS);
        assertEquals(5, TestDlc.BEATS.size());
        assertTrue(TestServer.log(dir).matches("(?s).*client 1 \\(/127\\.0\\.0\\.1:\\d+\\) connected.*"), TestServer.log(dir));
    }

    @Test
    void severalClientsMayBeLoadedAndTheServerWaitsForAllOfThem() throws Exception {
        String two = "dlcName=" + TestDlc.class.getName() + "," + TestDlc.class.getName();
        int status = runToTheEnd("dlcEnabled=true", two, HEADLESS_CI, LOCKSTEP, "interlockEnabled=true");
        assertEquals(ExitStatus.OK, status, TestServer.log(dir));
        assertEquals(10, TestDlc.BEATS.size());
    }

    @Test
    void aClientStillWaitingItsTurnWhenTheRunStopsIsNeverStarted() throws Exception {
        // The first robot's initialize() hangs; the second waits for it, at most connectTimeout. The
        // run is stopped meanwhile: the second must not be started on the stopped server afterwards.
        SlowStartDlc.reset();
        RunningServer server = TestServer.start(dir, "dlcEnabled=true",
                "dlcName=" + SlowStartDlc.class.getName() + "," + TestDlc.class.getName(), "connectTimeout=1",
                LOCKSTEP, "interlockEnabled=true", "enableNetworkClients=false");
        assertTrue(SlowStartDlc.entered.await(10, TimeUnit.SECONDS), TestServer.log(dir));
        server.stop();
        Thread.sleep(1500);
        assertFalse(TestDlc.CALLS.contains("initialize"), "started after the run stopped: " + TestDlc.CALLS
                + "\n" + TestServer.log(dir));
        String log = TestServer.log(dir);
        assertFalse(log.contains("dlc " + TestDlc.class.getName()), "its thread had to be ended\n" + log);
    }

    @Test
    void aClientWhoseInitializeFailsStopsTheServerWithOneLineAndANonZeroStatus() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", "dlcName=" + FailingDlc.class.getName());
        assertEquals(ExitStatus.CLIENT_FAILED, status);
        String log = TestServer.log(dir);
        assertTrue(log.contains("X ") && log.contains("client " + FailingDlc.class.getName()
                + ": initialize() failed: java.io.IOException: no robot today"), log);
        assertFalse(log.contains("\tat "), "no stack dump");
    }

    @Test
    void aFailingClientAmongSeveralMakesTheStatusNonZero() throws Exception {
        int status = runToTheEnd("dlcEnabled=true", "dlcName=" + TestDlc.class.getName() + "," + FailingDlc.class.getName(),
                HEADLESS_CI);
        assertEquals(ExitStatus.CLIENT_FAILED, status);
    }

    @Test
    void aClientThatFailsDuringTheRunMakesTheStatusNonZeroWhateverEndsTheRun() throws Exception {
        // The other robot goes on to maxSimulationTime: the failure did not stop it, but the run did
        // not go as asked.
        RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcName=" + ErrorDlc.class.getName() + ","
                + TirelessDlc.class.getName(), LOCKSTEP, "interlockEnabled=true", "maxSimulationTime=2");
        assertEquals(OptionalInt.of(ExitStatus.CLIENT_FAILED), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
        assertEquals("client failed: client " + ErrorDlc.class.getName() + ": run() failed: java.lang.AssertionError:"
                + " the robot's own check failed", server.getStopReason().replaceFirst(" at .*", ""));
        String log = TestServer.log(dir);
        assertTrue(log.contains("maxSimulationTime 2.0 s reached"), log);
        assertTrue(log.contains("The run ended (max-simulation-time) after a loaded client failed"), log);
        // Alone, the failed robot leaves the floor deserted, which ends the run: with status 2 too.
        TestDlc.reset();
        assertEquals(ExitStatus.CLIENT_FAILED, runToTheEnd("dlcEnabled=true", "dlcName=" + ErrorDlc.class.getName(),
                LOCKSTEP, "interlockEnabled=true", "enableNetworkClients=false", "maxSimulationTime=30"));
    }

    @Test
    void aHandlerThatRecursesWithoutEndFailsItsClientAloneEvenCalledDirectly() throws Exception {
        // Called directly, on the thread that runs the simulation: the StackOverflowError ended that
        // thread and, with it, the whole server (exit status 70), where over a pipe the client failed alone.
        RecursingDlc.internalError = false;
        RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcSetIO=true", "dlcName="
                + RecursingDlc.class.getName() + "," + TirelessDlc.class.getName(), LOCKSTEP, "interlockEnabled=true",
                "maxSimulationTime=2");
        assertEquals(OptionalInt.of(ExitStatus.CLIENT_FAILED), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
        assertTrue(server.getStopReason().startsWith("client failed: client " + RecursingDlc.class.getName()
                + ": a handler failed: java.lang.StackOverflowError"), server.getStopReason());
        assertTrue(TestServer.log(dir).contains("maxSimulationTime 2.0 s reached"), "the other robot went on");
    }

    @Test
    void anErrorThatEndsTheSimulationThreadStopsTheRunWithStatus70() throws Exception {
        RecursingDlc.internalError = true;
        try {
            RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcSetIO=true", "dlcName="
                    + RecursingDlc.class.getName(), LOCKSTEP, "interlockEnabled=true", "maxSimulationTime=2");
            assertEquals(OptionalInt.of(ExitStatus.FATAL_ERROR), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
            assertEquals("the simulation failed: java.lang.InternalError: made up by the test", server.getStopReason());
            assertTrue(TestServer.log(dir).contains("The simulation failed and stops: java.lang.InternalError"),
                    TestServer.log(dir));
        } finally {
            RecursingDlc.internalError = false;
        }
    }

    @Test
    void aClientWhoseRunThrowsAtOnceEndsTheRunAtOnceEveryTime() throws Exception {
        // Its pipe was closed before the clock started, and the clock waited for the pipe to be read
        // "to its end" until connectTimeout (here a minute: the test's timeout would end it first).
        for (int i = 0; i < 3; i++) {
            int status = runToTheEnd("dlcEnabled=true", "dlcName=" + RunThrowsDlc.class.getName(), LOCKSTEP,
                    "interlockEnabled=true", "enableNetworkClients=false", "maxSimulationTime=60", "connectTimeout=60");
            assertEquals(ExitStatus.CLIENT_FAILED, status, TestServer.log(dir));
            String log = TestServer.log(dir);
            assertFalse(log.contains("has not finished"), log);
            assertTrue(log.contains(" 0000.000: client " + RunThrowsDlc.class.getName()
                    + ": run() failed: java.lang.IllegalStateException: no run today"), log);
        }
    }

    @Test
    void aSimulationTaskThatFailsMakesTheRunsStatus70ThoughTheSimulationGoesOn() throws Exception {
        // A defect of the simulator's own: the run went on and said status 0, so a sweep counted it.
        RunningServer server = TestServer.start(dir, "dlcEnabled=true", "dlcName=" + TirelessDlc.class.getName(),
                "simulationSpeed=1", "maxSimulationTime=1");
        server.getSimulation().getScheduler().schedule(0.5, 0, t -> {
            throw new IllegalStateException("a defect");
        });
        assertEquals(OptionalInt.of(ExitStatus.FATAL_ERROR), server.awaitExit(20, TimeUnit.SECONDS), TestServer.log(dir));
        assertTrue(server.getStopReason().startsWith("a simulation task failed: java.lang.IllegalStateException: a defect at "),
                server.getStopReason());
        String log = TestServer.log(dir);
        assertTrue(log.contains("maxSimulationTime 1.0 s reached"), "the simulation went on: " + log);
        assertTrue(log.contains("\tat "), "the whole stack, for the report: " + log);
    }

    @Test
    void aMissingClassOrOneThatIsNotAClientIsAClientFailure() {
        StartupException missing = assertThrows(StartupException.class,
                () -> TestServer.start(dir, "dlcEnabled=true", "dlcName=no.such.Robot"));
        assertEquals("client class no.such.Robot not found on the class path (dlcName)", missing.getMessage());
        assertEquals(ExitStatus.CLIENT_FAILED, missing.getExitStatus(), "a client that cannot even be loaded failed");
        assertTrue(TestServer.log(dir).contains("Fatal error: client class no.such.Robot not found"));
        StartupException notAClient = assertThrows(StartupException.class,
                () -> TestServer.start(dir, "dlcEnabled=true", "dlcName=" + NotAClient.class.getName()));
        assertTrue(notAClient.getMessage().endsWith("does not implement rp1.rossum.RsRunnable"), notAClient.getMessage());
        assertEquals(ExitStatus.CLIENT_FAILED, notAClient.getExitStatus());
    }

    @Test
    void maxSimulationTimeStopsTheServerAtThatTime() throws Exception {
        String tireless = "dlcName=" + TirelessDlc.class.getName();
        int status = runToTheEnd("dlcEnabled=true", tireless, LOCKSTEP, "interlockEnabled=true", "maxSimulationTime=2.5");
        assertEquals(ExitStatus.OK, status);
        List<Double> beats = TestDlc.BEATS;
        assertTrue(beats.size() >= 24 && beats.size() <= 25, "beats up to 2.5 s: " + beats.size());
        assertTrue(beats.get(beats.size() - 1) <= 2.5 + 1e-9, String.valueOf(beats));
        assertTrue(TestServer.log(dir).contains("maxSimulationTime 2.5 s reached"));
        assertTrue(Arrays.asList(TestServer.log(dir).split("\n")).stream().anyMatch(l -> l.contains(" 0002.500: maxSimulationTime")));
    }
}
