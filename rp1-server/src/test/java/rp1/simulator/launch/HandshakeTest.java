package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.EOFException;
import java.io.IOException;
import java.net.SocketException;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The CONNECT/ACCEPT handshake with raw bytes (protocol.md section 4.2), and connections that fail it. */
@Timeout(30)
class HandshakeTest {
    @TempDir
    Path dir;
    private RunningServer server;

    @BeforeEach
    void start() throws Exception {
        // Its clients use timeouts without placing a robot: time must run without waiting for one.
        server = TestServer.start(dir, "connectTimeout=0.3", "simulationSpeed=100", "waitForClients=0");
    }

    @AfterEach
    void stop() throws Exception {
        server.stop();
    }

    @Test
    void acceptEchoesTheClientsIdAndKeyWithSequenceOneAndEventsFollowWithTwo() throws Exception {
        try (RawClient c = RawClient.open(server.getPort())) {
            c.handshake(7, 9);
            c.sendBody();
            c.sendTimeout(0.5, 1);
            int[] header = c.readHeader();
            assertArrayEquals(new int[] {0, 7, 9, 2, RawClient.EVENT}, header, "the first event after ACCEPT (1)");
            assertEquals(RawClient.EVT_TIMEOUT, c.in.readInt());
            TestServer.awaitLog(dir, "client 1 (/127.0.0.1:" + c.socket.getLocalPort() + ") connected (client id 7, key 9)");
        }
    }

    @Test
    void theAcceptBytesAreThoseOfProtocolSection13() throws Exception {
        try (RawClient c = RawClient.open(server.getPort())) {
            c.out.write(new byte[] {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1});
            c.out.flush();
            byte[] accept = new byte[20];
            c.in.readFully(accept);
            assertArrayEquals(new byte[] {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2}, accept);
        }
    }

    @Test
    void aSilentConnectionTimesOutWhileOthersGetIn() throws Exception {
        try (RawClient silent = RawClient.open(server.getPort())) {
            try (RawClient other = RawClient.connected(server.getPort())) {
                other.sendTimeout(0.1, 1);
                assertEquals(1, other.awaitEvent(RawClient.EVT_TIMEOUT).value, "served although client 1 is silent");
            }
            TestServer.awaitLog(dir, "client 1 (/127.0.0.1:" + silent.socket.getLocalPort()
                    + "): handshake failed: no CONNECT within 300 ms (connectTimeout)");
            TestServer.awaitLog(dir, "client 1 (/127.0.0.1:" + silent.socket.getLocalPort() + ") disconnected");
            assertClosedByServer(silent);
        }
    }

    @Test
    void aWrongVersionOrTransactionIsRefusedAndLogged() throws Exception {
        try (RawClient c = RawClient.open(server.getPort())) {
            c.out.writeInt(3);
            c.out.write(new byte[16]);
            c.out.flush();
            TestServer.awaitLog(dir, "client 1 (/127.0.0.1:" + c.socket.getLocalPort()
                    + "): handshake failed: CONNECT version: expected 0, got 3");
            assertClosedByServer(c);
        }
        try (RawClient c = RawClient.open(server.getPort())) {
            c.out.write(new byte[16]);
            c.out.writeInt(RawClient.REQUEST);
            c.out.flush();
            TestServer.awaitLog(dir, "client 2 (/127.0.0.1:" + c.socket.getLocalPort()
                    + "): handshake failed: CONNECT transaction code: expected CONNECT (1), got REQUEST (4)");
            assertClosedByServer(c);
        }
    }

    /** The server closed the connection: the next read sees the end of the stream or a reset. */
    private static void assertClosedByServer(RawClient c) {
        int next;
        try {
            next = c.in.read();
        } catch (EOFException | SocketException e) {
            return;
        } catch (IOException e) {
            throw new AssertionError("expected the connection to be closed, got " + e, e);
        }
        assertEquals(-1, next, "the server closed the connection");
    }
}
