package rp1.simulator.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsLogAdapter;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * Many connections, each within its own budget, cannot together take the memory every client needs:
 * 47 clients each holding 4 MB of a body that never ended ran a 200 MB server out of memory.
 */
@Timeout(30)
class AllClientsBudgetTest {
    private final List<String> lines = new ArrayList<>();
    private final RsLogAdapter log = new RsLogAdapter() {
        @Override
        public void logIt(String level, String message) {
            synchronized (lines) {
                lines.add(message);
            }
        }
    };

    @Test
    void aClientWhoseMessageWouldTakeAllTheClientsBeyondTheirSharedBudgetIsDisconnected() throws Exception {
        Simulation simulation = new Simulation(RsPlanParser.parseFile(
                Paths.get(System.getProperty("rp1.root", ".")).resolve("FloorPlans/WhiteRoom.txt")),
                SimulationSettings.lockstep(0.05, 1L), log);
        ClientRegistry clients = new ClientRegistry(log);
        ClientListener listener = ClientListener.bind("127.0.0.1", 0, simulation, clients, log,
                new ClientListener.Settings(10.0, 10000).withAllClients(1_000_000));
        listener.start();
        try (Socket first = new Socket("127.0.0.1", listener.getPort());
             Socket second = new Socket("127.0.0.1", listener.getPort())) {
            halfABody(first, 600_000);
            awaitLine("client 1 (");
            Thread.sleep(300); // the network thread has read the first one's 600 kB
            halfABody(second, 600_000);
            String refused = awaitLine("over budget: the clients' incomplete messages would hold");
            assertTrue(refused.startsWith("client 2 ("), refused);
            assertTrue(refused.contains("more than the 1000000 they all may (a quarter of the server's memory)"), refused);
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (clients.size() != 1 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertEquals(1, clients.size(), "the first client, within the budget, is still connected");
        } finally {
            listener.close();
        }
    }

    /** CONNECT, then the start of a body of one polygon of 60,000 vertices and {@code bytes} of it. */
    private static void halfABody(Socket s, int bytes) throws IOException {
        DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
        for (int field : new int[] {0, 0, 0, 0, 1}) {
            out.writeInt(field);
        }
        out.flush();
        DataInputStream in = new DataInputStream(s.getInputStream());
        int[] accept = {in.readInt(), in.readInt(), in.readInt(), in.readInt(), in.readInt()};
        for (int field : new int[] {0, accept[1], accept[2], 2, 5}) {
            out.writeInt(field);
        }
        out.writeUTF("long");
        out.writeInt(1);
        out.writeInt(1);
        out.writeInt(3);
        out.writeInt(60000);
        try {
            for (int i = 0; i < bytes / 8; i++) {
                out.writeDouble(i);
            }
            out.flush();
        } catch (IOException hungUp) {
            // The server may disconnect a client before it has sent all: that is what is tested.
        }
    }

    private String awaitLine(String part) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < deadline) {
            synchronized (lines) {
                for (String l : lines) {
                    if (l.contains(part)) {
                        return l;
                    }
                }
            }
            Thread.sleep(10);
        }
        synchronized (lines) {
            throw new AssertionError("no line with \"" + part + "\" in " + lines);
        }
    }
}
