package rp1.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;
import rp1.rossum.RsProperties;

/** Clients joining one after another: connect, handshake, body, placement request, placement event. */
final class Connecting {
    private Connecting() {
    }

    /** Milliseconds until {@code count} clients, joining one after another, have all been placed. */
    static double placeInARow(int port, int count) throws IOException, InterruptedException {
        RsProperties p = new RsProperties();
        p.hostName = "127.0.0.1";
        p.port = port;
        List<Joiner> clients = new ArrayList<>();
        long start = System.nanoTime();
        for (int i = 0; i < count; i++) {
            clients.add(joinAndPlace(p, i));
        }
        double millis = (System.nanoTime() - start) * 1e-6;
        for (Joiner c : clients) {
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

    /** A client that can end its session. */
    private static final class Joiner extends RsClient {
        void leave() {
            shutdown();
        }
    }

    private static Joiner joinAndPlace(RsProperties p, int i) throws IOException, InterruptedException {
        CountDownLatch placed = new CountDownLatch(1);
        Joiner c = new Joiner();
        c.setLogger(Quiet.LOG);
        c.initialize(p);
        RsBody body = new RsBody("joiner " + i);
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.05));
        c.sendBodySpecification(body);
        c.addPlacementEventHandler(e -> {
            if (e.valid) {
                placed.countDown();
            } else {
                c.sendPlacementRequest("$random");
            }
        });
        Thread loop = new Thread(c, "joiner " + i);
        loop.setDaemon(true);
        loop.start();
        c.sendPlacementRequest("$random");
        if (!placed.await(10, TimeUnit.SECONDS)) {
            throw new IOException("client " + i + " was not placed within 10 s");
        }
        return c;
    }
}
