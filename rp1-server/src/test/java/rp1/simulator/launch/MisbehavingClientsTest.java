package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsHeartbeatEvent;
import rp1.simulator.world.Robot;

/**
 * Clients that break the protocol, vanish mid-message, stay silent or stop reading are dropped, each
 * with a log line naming it and the reason, while a well-behaved client's heartbeats keep arriving in
 * sequence and on simulated time, and the server keeps accepting.
 */
@Timeout(60)
class MisbehavingClientsTest {
    @TempDir
    Path dir;

    private static String who(RawClient c) {
        return "(/127.0.0.1:" + c.socket.getLocalPort() + ")";
    }

    @Test
    void misbehavingClientsAreDroppedWhileAWellBehavedClientsHeartbeatsArriveOnTime() throws Exception {
        // Its clients use heartbeats without placing a robot: time must run without waiting for one.
        RunningServer server = TestServer.start(dir, "simulationSpeed=10", "clientQueueLimit=16", "connectTimeout=0.5",
                "waitForClients=0");
        int port = server.getPort();
        try {
            TcpRobot good = TcpRobot.connect(port, "good").startLoop();
            good.sendHeartbeatRequest(0.1);
            good.await(RsHeartbeatEvent.class, e -> e.sequence >= 2);

            RawClient garbage = RawClient.connected(port);
            garbage.out.write("GET / HTTP/1.1\r\nHost: rp1\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
            garbage.out.flush();

            RawClient wrongVersion = RawClient.connected(port);
            wrongVersion.out.writeInt(1);
            wrongVersion.out.write(new byte[16]);
            wrongVersion.out.flush();

            RawClient absurd = RawClient.connected(port);
            absurd.header(RawClient.BODY);
            absurd.out.writeUTF("huge");
            absurd.out.writeInt(1_000_000_000);
            absurd.out.flush();

            RawClient vanishing = RawClient.connected(port);
            vanishing.sendBody();
            vanishing.header(RawClient.REQUEST);
            vanishing.out.writeInt(0);
            vanishing.out.writeInt(0);
            vanishing.out.writeShort(0x3ff0);
            vanishing.out.flush();
            vanishing.close();

            RawClient deaf = RawClient.openWithSmallBuffer(port);
            deaf.handshake(0, 0);
            deaf.sendBody();
            deaf.sendHeartbeat(0.0005);

            RawClient silent = RawClient.open(port);

            String dropped = ": RsConnection terminating due to exception on input: ";
            TestServer.awaitLog(dir, who(garbage) + dropped + "header version: expected 0, got 1195725856");
            TestServer.awaitLog(dir, who(wrongVersion) + dropped + "header version: expected 0, got 1");
            TestServer.awaitLog(dir, who(absurd) + dropped + "nParts: 1000000000 is outside the accepted range");
            TestServer.awaitLog(dir, who(vanishing) + dropped + "timeout duration: stream ended in the middle of a message");
            TestServer.awaitLog(dir, who(deaf) + ": closing the connection: not reading: 16 messages waiting, "
                    + "the limit is 16 (clientQueueLimit)");
            TestServer.awaitLog(dir, who(silent) + ": handshake failed: no CONNECT within 500 ms");
            for (RawClient c : new RawClient[] {garbage, wrongVersion, absurd, vanishing, deaf, silent}) {
                TestServer.awaitLog(dir, who(c) + " disconnected");
                c.close();
            }

            assertOnlyTheGoodRobotIsLeft(server);

            try (RawClient late = RawClient.connected(port)) {
                late.sendTimeout(0.0, 1);
                assertEquals(1, late.awaitEvent(RawClient.EVT_TIMEOUT).value, "the server still accepts and serves");
            }
            int seen = good.events(RsHeartbeatEvent.class).size();
            good.await(RsHeartbeatEvent.class, e -> e.sequence >= seen + 5);
            assertHeartbeatsInSequenceAtTheirTimes(good.events(RsHeartbeatEvent.class));
            good.leave();
        } finally {
            server.stop();
        }
    }

    /**
     * A body with no part in it is refused with the client's session, naming the field, and the run's
     * recording goes on whole: accepted, such a body could not be recorded, and the recording stopped
     * there for every client (the run then ended with status 4).
     */
    @Test
    void anEmptyBodyEndsItsSessionAndTheRecordingStaysWhole() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=10", "waitForClients=0", "recordFileName=run.rec");
        int port = server.getPort();
        try {
            TcpRobot good = TcpRobot.connect(port, "good").startLoop();
            good.sendHeartbeatRequest(0.1);
            good.await(RsHeartbeatEvent.class, e -> e.sequence >= 2);
            RawClient empty = RawClient.connected(port);
            empty.header(RawClient.BODY);
            empty.out.writeUTF("");
            empty.out.writeInt(0);
            empty.out.flush();
            TestServer.awaitLog(dir, who(empty) + ": RsConnection terminating due to exception on input: nParts: a body"
                    + " needs at least one part");
            int seen = good.events(RsHeartbeatEvent.class).size();
            good.await(RsHeartbeatEvent.class, e -> e.sequence >= seen + 3);
            empty.close();
            good.leave();
        } finally {
            server.stop();
        }
        assertEquals(ExitStatus.OK, server.awaitExit());
        assertTrue(java.nio.file.Files.readString(dir.resolve("run.rec")).contains("\nend "), "the recording is whole");
    }

    /** The robots of the dropped clients that had one (the vanishing and the deaf client) have left the world. */
    private static void assertOnlyTheGoodRobotIsLeft(RunningServer server) throws InterruptedException {
        await(() -> server.getSimulation().getWorld().getRobots().size() == 1, Duration.ofSeconds(10),
                "the robots of the dropped clients left the world");
        List<Robot> robots = server.getSimulation().getWorld().getRobots();
        assertEquals(1, robots.size(), "robots: " + robots);
        assertEquals("good", robots.get(0).getLabel());
    }

    private static void assertHeartbeatsInSequenceAtTheirTimes(List<RsHeartbeatEvent> beats) {
        RsHeartbeatEvent first = beats.get(0);
        for (int k = 0; k < beats.size(); k++) {
            RsHeartbeatEvent b = beats.get(k);
            assertEquals(k + 1, b.sequence, "no beat lost or repeated");
            assertEquals(first.simTime + 0.1 * k, b.simTime, 1e-9, "beat " + b.sequence + " at its simulated time");
        }
        assertTrue(beats.size() >= 10, "beats kept coming: " + beats.size());
    }
}
