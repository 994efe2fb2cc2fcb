package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Clients sending messages of megabytes a kilobyte at a time cost the server what the bytes cost,
 * once: the other clients' round trips go on meanwhile, and every long message arrives whole. (When
 * each arrival decoded the message again from its start, these five bodies took minutes to decode,
 * far beyond this test's time limit.)
 */
@Timeout(60)
class TricklingClientsTest {
    private static final int TRICKLERS = 5;
    private static final int PIECE = 1024;

    @TempDir
    Path dir;

    /** A body of three shapes of 65536 vertices each, about 3 MB: many small fields. */
    private static byte[] longBody(RawClient c) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeUTF("long");
        out.writeInt(3);
        for (int part = 1; part <= 3; part++) {
            out.writeInt(part);
            out.writeInt(3);
            out.writeInt(65536);
            for (int i = 0; i < 65536; i++) {
                out.writeDouble(0.1 * Math.cos(i * 2 * Math.PI / 65536));
                out.writeDouble(0.1 * Math.sin(i * 2 * Math.PI / 65536));
            }
            out.writeUTF("shape");
            for (int colour = 0; colour < 4; colour++) {
                out.writeInt(0);
            }
        }
        c.header(RawClient.BODY);
        c.out.flush();
        return bytes.toByteArray();
    }

    @Test
    void longMessagesTricklingInDoNotHoldUpTheOtherClients() throws Exception {
        RunningServer server = TestServer.start(dir, "simulationSpeed=10", "waitForClients=0");
        List<RawClient> tricklers = new ArrayList<>();
        try (RawClient good = RawClient.connected(server.getPort())) {
            List<byte[]> messages = new ArrayList<>();
            for (int i = 0; i < TRICKLERS; i++) {
                RawClient c = RawClient.connected(server.getPort());
                tricklers.add(c);
                messages.add(longBody(c));
            }
            int length = messages.get(0).length;
            int roundTrips = 0;
            for (int at = 0, piece = 0; at < length; at += PIECE, piece++) {
                for (int i = 0; i < TRICKLERS; i++) {
                    tricklers.get(i).out.write(messages.get(i), at, Math.min(PIECE, length - at));
                    tricklers.get(i).out.flush();
                }
                // The round trip also makes each piece a read of its own, as from a client that trickles.
                good.sendTimeout(0.0, piece);
                assertEquals(piece, good.awaitEvent(RawClient.EVT_TIMEOUT).value, "a round trip meanwhile");
                roundTrips++;
            }
            for (int i = 0; i < TRICKLERS; i++) {
                RawClient c = tricklers.get(i);
                c.sendTimeout(0.0, -1 - i);
                assertEquals(-1 - i, c.awaitEvent(RawClient.EVT_TIMEOUT).value,
                        "trickler " + i + "'s long message was read whole and the next one answered");
            }
            assertEquals((length + PIECE - 1) / PIECE, roundTrips);
        } finally {
            for (RawClient c : tricklers) {
                c.close();
            }
            server.stop();
        }
    }
}
