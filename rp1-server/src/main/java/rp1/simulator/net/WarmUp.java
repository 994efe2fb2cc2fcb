package rp1.simulator.net;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;

import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * Prepares the server for its first network client before its port opens: a few clients, written as
 * raw bytes, join a scratch simulation of the same floor plan over loopback (handshake, body,
 * placement, motion, departure), so that the classes they need are loaded and their code has run
 * before a real client waits on it. Each server does it once, before its port opens. The scratch
 * simulation gets a plan of its own: a {@code World} gives its plan the world's random source, so
 * sharing the real plan would leave random target selection drawing from the scratch source instead
 * of the seeded one, and the run would no longer be what its recording replays.
 */
public final class WarmUp {
    private static final int CLIENTS = 300;
    private static final int TIMEOUT_MILLIS = 2000;
    private WarmUp() {
    }

    /**
     * Runs the warm-up on {@code ownPlan}, which must not be the real simulation's plan (a copy of it
     * will do). Failures only mean a colder first client.
     */
    public static void run(RsPlan ownPlan) {
        RsLogInterface quiet = new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
            }
        };
        Simulation scratch = new Simulation(ownPlan, SimulationSettings.lockstep(0.05, 1L), quiet);
        ClientRegistry registry = new ClientRegistry(quiet);
        Thread loop = new Thread(scratch::run, "warm-up simulation");
        loop.setDaemon(true);
        loop.start();
        ClientListener listener = null;
        try {
            listener = ClientListener.bind("127.0.0.1", 0, scratch, registry, quiet, new ClientListener.Settings(2.0, 1000));
            listener.start();
            for (int i = 0; i < CLIENTS; i++) {
                join(listener.getPort());
            }
        } catch (IOException e) {
            quiet.log("warm-up ended early: " + e.getMessage());
        } finally {
            if (listener != null) {
                listener.close();
            }
            registry.closeAll("warm-up over");
            scratch.shutdown();
        }
    }

    /**
     * One client: handshake, a round body, a random placement and a motion; it acknowledges the
     * placement, reads the start of the next message and leaves without a word.
     */
    private static void join(int port) throws IOException {
        try (Socket s = new Socket()) {
            s.setTcpNoDelay(true);
            s.setSoTimeout(TIMEOUT_MILLIS);
            s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), TIMEOUT_MILLIS);
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
            header(out, 0, 1);
            out.flush();
            in.readFully(new byte[20]);
            body(out);
            request(out, 2, 7);
            out.writeInt(7);
            out.writeUTF("$random");
            request(out, 3, 3);
            out.writeDouble(0.2);
            out.writeDouble(0.0);
            out.writeDouble(0.1);
            out.flush();
            byte[] prefix = new byte[20 + 16];
            in.readFully(prefix);
            header(out, 4, 6);
            out.write(prefix, 32, 4);
            out.flush();
            in.readFully(new byte[20]);
        }
    }

    private static void header(DataOutputStream out, int sequence, int code) throws IOException {
        out.writeInt(0);
        out.writeInt(0);
        out.writeInt(0);
        out.writeInt(sequence);
        out.writeInt(code);
    }

    private static void request(DataOutputStream out, int sequence, int code) throws IOException {
        header(out, sequence, 4);
        out.writeInt(code);
        out.writeInt(0);
    }

    /** A body "warm" with one circle of radius 5 cm (docs/protocol.md section 8.7 shows the layout). */
    private static void body(DataOutputStream out) throws IOException {
        header(out, 1, 5);
        out.writeUTF("warm");
        out.writeInt(1);
        out.writeInt(1);
        out.writeInt(2);
        out.writeDouble(0.0);
        out.writeDouble(0.0);
        out.writeDouble(0.05);
        out.writeUTF("c");
        for (int i = 0; i < 4; i++) {
            out.writeInt(1);
            out.writeInt(255);
            out.writeInt(200);
            out.writeInt(0);
        }
    }
}
