package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Starting the server from properties files, good and bad (behavior.md sections 2 and 3.1). */
@Timeout(30)
class ServerStartupTest {
    @TempDir
    Path dir;

    @Test
    void startsFromAPropertiesFileListensOnAFreePortAndLogsInTheServerFormat() throws Exception {
        RunningServer server = TestServer.start(dir, "randomSeed=42");
        try {
            assertTrue(server.getPort() > 0);
            try (RawClient c = RawClient.connected(server.getPort())) {
                TestServer.awaitLog(dir, "client 1 (/127.0.0.1:" + c.socket.getLocalPort() + ") connected");
            }
            TestServer.awaitLog(dir, "client 1 (/127.0.0.1:");
        } finally {
            assertEquals(ExitStatus.OK, server.stop());
        }
        String log = TestServer.log(dir);
        String first = log.split("\n")[0];
        assertTrue(first.matches("X \\d{1,2}:\\d\\d:\\d\\d\\.\\d{3} 0000\\.000: STARTING SIMULATOR SESSION"), first);
        assertTrue(log.contains("randomSeed=42"), log);
        assertTrue(log.contains("GUI is disabled"), log);
        assertTrue(log.contains("disconnected"), log);
        assertTrue(log.contains("Shutting down simulator"), log);
        assertTrue(log.contains("  Total Memory used by JVM: "), "the original's closing lines");
    }

    @Test
    void aRefusedPlacementIsLoggedWithItsReason() throws Exception {
        RunningServer server = TestServer.start(dir, "waitForClients=0");
        try {
            TcpRobot first = TcpRobot.connect(server.getPort(), "first").startLoop();
            first.sendPlacementRequest("p1");
            first.await(rp1.rossum.event.RsPlacementEvent.class, e -> e.valid);
            TcpRobot second = TcpRobot.connect(server.getPort(), "second").startLoop();
            second.sendPlacementRequest("p1");
            second.await(rp1.rossum.event.RsPlacementEvent.class, e -> !e.valid);
            String log = TestServer.awaitLog(dir, "placement 'p1' refused: another robot is in the way");
            assertTrue(log.matches("(?s).*client 2 \\([^)]*\\): placement 'p1' refused: another robot is in the way.*"), log);
            first.leave();
            second.leave();
        } finally {
            server.stop();
        }
    }

    @Test
    void withoutASeedTheServerPicksOneAndSaysHowToRepeatTheRun() throws Exception {
        RunningServer server = TestServer.start(dir);
        server.stop();
        assertTrue(TestServer.log(dir).matches("(?s).*randomSeed=-?\\d+; set it to repeat this run.*"));
    }

    @Test
    void aBadValueNamesTheFileTheKeyAndTheValueAndNothingStarts() {
        for (String bad : new String[] {"port=77x", "simulationSpeed=5000", "logToFile=yes", "modelingFrameRate=fast",
                                         "clientQueueLimit=0", "clientMessageBudget=5000000", "clientTimeoutBudget=-1"}) {
            StartupException e = assertThrows(StartupException.class, () -> TestServer.start(dir, bad));
            String key = bad.substring(0, bad.indexOf('='));
            String value = bad.substring(bad.indexOf('=') + 1);
            assertTrue(e.getMessage().contains(TestServer.PROPERTIES), e.getMessage());
            assertTrue(e.getMessage().contains(key + "=" + value), e.getMessage());
            assertEquals(ExitStatus.STARTUP_FAILED, e.getExitStatus());
            assertFalse(Files.exists(dir.resolve(TestServer.LOG)), "not even the log was opened for " + bad);
        }
    }

    @Test
    void inconsistentKeysAreRefused() {
        StartupException noName = assertThrows(StartupException.class, () -> TestServer.start(dir, "dlcEnabled=true"));
        assertTrue(noName.getMessage().contains("dlcName"), noName.getMessage());
        StartupException forever = assertThrows(StartupException.class,
                () -> TestServer.start(dir, "exitWhenClientsDone=true"));
        assertTrue(forever.getMessage().contains("exitWhenClientsDone"), forever.getMessage());
        StartupException max = assertThrows(StartupException.class, () -> TestServer.start(dir, "simulationSpeed=max"));
        assertTrue(max.getMessage().contains("interlockEnabled"), max.getMessage());
    }

    @Test
    void aMissingPropertiesFileSaysWhereItWasLookedFor() {
        StartupException e = assertThrows(StartupException.class,
                () -> ServerLauncher.start(new String[] {"-p", "nowhere.ini"}, dir));
        assertTrue(e.getMessage().contains("nowhere.ini"), e.getMessage());
        assertTrue(e.getMessage().contains(dir.toAbsolutePath().toString()), e.getMessage());
        StartupException noValue = assertThrows(StartupException.class,
                () -> ServerLauncher.start(new String[] {"-f"}, dir));
        assertTrue(noValue.getMessage().contains("-f"), noValue.getMessage());
    }

    @Test
    void aFloorPlanErrorGivesFileLineAndColumnInTheMessageAndTheLog() throws Exception {
        TestServer.write(dir);
        Files.write(dir.resolve("broken.txt"), "caption: \"x\";\nwall a { geometry: 0, 0, 1; }\n".getBytes(StandardCharsets.UTF_8));
        StartupException e = assertThrows(StartupException.class, () -> ServerLauncher.start(
                new String[] {"-p", TestServer.PROPERTIES, "-f", "broken.txt"}, dir, LaunchOptions.defaults().withPort(0)));
        assertTrue(e.getMessage().matches("(?s).*broken\\.txt:2:\\d+: .*"), e.getMessage());
        assertEquals(ExitStatus.STARTUP_FAILED, e.getExitStatus());
        String log = TestServer.log(dir);
        assertTrue(log.contains("X ") && log.contains("Fatal error: ") && log.contains("broken.txt:2:"), log);
    }

    @Test
    void aPortInUseIsAClearErrorWithANonZeroStatus() throws Exception {
        try (ServerSocket taken = new ServerSocket()) {
            taken.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            TestServer.write(dir);
            StartupException e = assertThrows(StartupException.class, () -> ServerLauncher.start(
                    new String[] {"-p", TestServer.PROPERTIES}, dir, LaunchOptions.defaults().withPort(taken.getLocalPort())));
            assertTrue(e.getMessage().contains("cannot listen on 127.0.0.1:" + taken.getLocalPort()), e.getMessage());
            assertEquals(ExitStatus.STARTUP_FAILED, e.getExitStatus());
        }
    }

    @Test
    void withNetworkClientsDisabledNoPortIsOpened() throws Exception {
        RunningServer server = TestServer.start(dir, "enableNetworkClients=false");
        assertEquals(-1, server.getPort());
        server.stop();
        assertTrue(TestServer.log(dir).contains("Network client connections disabled"));
    }

    @Test
    void theGuiHookIsCalledWhenTheGuiIsEnabledAndClosedAtTheEnd() throws Exception {
        TestServer.write(dir, "enableGUI=true");
        boolean[] closed = {false};
        ViewHook view = context -> {
            context.log.log("test view open on " + context.simulation.getWorld().getPlan().getCaption());
            return () -> closed[0] = true;
        };
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                LaunchOptions.defaults().withPort(0).withView(view));
        server.stop();
        assertTrue(closed[0]);
        assertTrue(TestServer.log(dir).contains("test view open on arena"));
    }

    @Test
    void withTheGuiAskedForButNoDisplayTheServerRunsHeadlessAndSaysSo() throws Exception {
        TestServer.write(dir, "enableGUI=true");
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES}, dir,
                LaunchOptions.defaults().withPort(0));
        server.stop();
        assertTrue(TestServer.log(dir).contains("GUI not available"), TestServer.log(dir));
        assertTrue(TestServer.log(dir).contains("running headless"));
    }
}
