package rp1.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/** Clients joining one after another: connect, handshake, body, placement request, placement event. */
final class Connecting {
    private Connecting() {
    }

    /** Milliseconds until {@code count} clients, joining one after another, have all been placed. */
    static double placeInARow(int port, int count) throws IOException, InterruptedException {
        List<NetRobot> clients = new ArrayList<>();
        long start = System.nanoTime();
        for (int i = 0; i < count; i++) {
            clients.add(joinAndPlace(port, i));
        }
        double millis = (System.nanoTime() - start) * 1e-6;
        for (NetRobot c : clients) {
            c.leave();
        }
        return millis;
    }

    /** Runs the client side of a join once against a server in this process, so that it is warm. */
    static void warmUp() throws Exception {
        rp1.simulator.launch.RunningServer server = BenchServer.start();
        try {
            placeInARow(server.getPort(), 20);
        } finally {
            server.stop();
        }
    }

    private static NetRobot joinAndPlace(int port, int i) throws IOException, InterruptedException {
        NetRobot c = new NetRobot(port, "joiner " + i, 0.05, new CountDownLatch(1)).place("$random");
        if (!c.placed().await(10, TimeUnit.SECONDS)) {
            throw new IOException("client " + i + " was not placed within 10 s");
        }
        return c;
    }
}
