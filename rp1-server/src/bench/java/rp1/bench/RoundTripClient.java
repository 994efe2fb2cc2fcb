package rp1.bench;

import java.io.IOException;
import java.util.concurrent.atomic.AtomicLong;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;

/**
 * Interlocked round trips as fast as they go: each timeout event's handler asks for the next
 * zero-length timeout, and the client library acknowledges the event after the handler. Loaded by
 * the server (in-process) or connected over TCP. Between measurements it rests: the handler stops
 * asking until {@link #measure} starts the next run.
 */
public class RoundTripClient extends RsClient implements RoundTrips {
    /** The most recently created instance (the server creates in-process ones itself). */
    static volatile RoundTripClient latest;

    private final AtomicLong roundTrips = new AtomicLong();
    private volatile boolean running;

    public RoundTripClient() {
        latest = this;
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = new RsBody("round trip");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.05));
        sendBodySpecification(body);
        addTimeoutEventHandler(e -> {
            roundTrips.incrementAndGet();
            if (running) {
                sendTimeoutRequest(0.0);
            }
        });
    }

    @Override
    public double measure(double seconds) throws InterruptedException {
        long n0 = roundTrips.get();
        long t0 = System.nanoTime();
        running = true;
        sendTimeoutRequest(0.0);
        Thread.sleep((long) (seconds * 1000));
        long n1 = roundTrips.get();
        double wall = (System.nanoTime() - t0) * 1e-9;
        running = false;
        Thread.sleep(50);
        return (n1 - n0) / wall;
    }

    @Override
    public void close() {
        shutdown();
    }
}
