package rp1.simulator.net;

import java.awt.Color;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsConnection;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.wire.RequestCodec;
import rp1.rossum.wire.WireCodes;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * Prepares the server for its first network client before its port opens: a few clients, speaking
 * the protocol through its codecs without the client library's threads, join a scratch simulation of
 * the same floor plan over loopback (handshake, body, placement, motion, departure), so that the
 * classes they need are loaded and their code has run before a real client waits on it. Each server does it once, before its port opens. The scratch
 * simulation gets a plan of its own: a {@code World} gives its plan the world's random source, so
 * sharing the real plan would leave random target selection drawing from the scratch source instead
 * of the seeded one, and the run would no longer be what its recording replays.
 */
public final class WarmUp {
    private static final int CLIENTS = 300;
    private static final int TIMEOUT_MILLIS = 2000;
    private static final byte[] BODY = warmBody();

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
     * placement, reads the start of the next message and leaves without a word. Every message is
     * encoded by the protocol's own codecs.
     */
    private static void join(int port) throws IOException {
        try (Socket s = new Socket()) {
            s.setTcpNoDelay(true);
            s.setSoTimeout(TIMEOUT_MILLIS);
            s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), TIMEOUT_MILLIS);
            OutputStream out = new BufferedOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
            WireIn wire = new WireIn(in);
            message(0, WireCodes.CONNECT).writeTo(out);
            out.flush();
            in.readFully(new byte[WireCodes.HEADER_BYTES]);
            message(1, WireCodes.BODY_SPECIFICATION).writeTo(out);
            out.write(BODY);
            write(out, 2, RequestCodec.placement("$random"));
            write(out, 3, RequestCodec.motion(new RsMotionRequest(0.2, 0.0, 0.1)));
            out.flush();
            in.readFully(new byte[WireCodes.HEADER_BYTES]);
            wire.i32("event code");
            wire.i32("event index");
            wire.f64("event simTime");
            int interlock = wire.i32("event interlock");
            message(4, WireCodes.INTERLOCK).i32(interlock).writeTo(out);
            out.flush();
            in.readFully(new byte[WireCodes.HEADER_BYTES]);
        }
    }

    /** A header with client id and key 0 (the warm-up's clients do not care what they are called). */
    private static WireOut message(int sequence, int code) {
        return new WireOut().header(0, 0, sequence, code);
    }

    private static void write(OutputStream out, int sequence, WireOut request) throws IOException {
        message(sequence, WireCodes.REQUEST).writeTo(out);
        request.writeTo(out);
    }

    /** A body "warm" with one circle of radius 5 cm, as its payload on the wire. */
    private static byte[] warmBody() {
        RsBody body = new RsBody("warm");
        RsBodyCircle circle = new RsBodyCircle(0.0, 0.0, 0.05);
        circle.setName("c");
        circle.setFillColor(new Color(255, 200, 0));
        circle.setLineColor(new Color(255, 200, 0));
        body.addPart(circle);
        return RsConnection.encodeBodySpecification(body);
    }
}
