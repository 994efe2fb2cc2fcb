package rp1.bench;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;
import rp1.rossum.RsProperties;

/**
 * A round robot over loopback TCP, as the network benchmarks use it: connected, body sent, its event
 * loop running on a daemon thread. {@link #place} asks for a placement and tries again at random until
 * one is valid.
 */
class NetRobot extends RsClient {
    private final String name;
    private final CountDownLatch placed;

    /** Connects to the server at {@code port} and sends a body of one circle of {@code radius}. */
    NetRobot(int port, String name, double radius, CountDownLatch placed) throws IOException {
        this.name = name;
        this.placed = placed;
        setLogger(Quiet.LOG);
        RsProperties p = new RsProperties();
        p.hostName = "127.0.0.1";
        p.port = port;
        initialize(p);
        RsBody body = new RsBody(name);
        body.addPart(new RsBodyCircle(0.0, 0.0, radius));
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            if (e.valid) {
                placed.countDown();
            } else {
                sendPlacementRequest("$random");
            }
        });
    }

    /** Starts the event loop and asks for {@code placement}; {@link #placed} counts down when placed. */
    NetRobot place(String placement) {
        Thread loop = new Thread(this, name);
        loop.setDaemon(true);
        loop.start();
        sendPlacementRequest(placement);
        return this;
    }

    CountDownLatch placed() {
        return placed;
    }

    /** Ends the session before the server goes. */
    void leave() {
        shutdown();
    }
}
