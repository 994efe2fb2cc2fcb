package rp1.simulator.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.Socket;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsLogAdapter;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;

/**
 * When accepting a connection fails (out of file descriptors), the network thread neither spins nor
 * floods the log: it tries again every {@value ClientListener#ACCEPT_PAUSE_MILLIS} ms, logs at most
 * once a second, and takes the waiting client once accepting works again.
 */
@Timeout(30)
class AcceptFailureTest {
    @Test
    // "try": the client socket `waiting` is never used in its try block; it only has to stay
    // connected, waiting in the backlog, while accepting fails.
    @SuppressWarnings("try")
    void aFailingAcceptIsRetriedAfterAPauseAndLoggedAtMostOnceASecond() throws Exception {
        List<String> lines = new ArrayList<>();
        RsLogAdapter log = new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                synchronized (lines) {
                    lines.add(message);
                }
            }
        };
        Simulation simulation = new Simulation(RsPlanParser.parseFile(
                Paths.get(System.getProperty("rp1.root", ".")).resolve("FloorPlans/WhiteRoom.txt")),
                SimulationSettings.lockstep(0.05, 1L), log);
        ClientRegistry clients = new ClientRegistry(log);
        AtomicBoolean failing = new AtomicBoolean(true);
        AtomicInteger attempts = new AtomicInteger();
        ClientListener.Settings settings = new ClientListener.Settings(10.0, 10000).withAcceptor(server -> {
            attempts.incrementAndGet();
            if (failing.get()) {
                throw new IOException("Too many open files");
            }
            return server.accept();
        });
        ClientListener listener = ClientListener.bind("127.0.0.1", 0, simulation, clients, log, settings);
        listener.start();
        try (Socket waiting = new Socket("127.0.0.1", listener.getPort())) {
            Thread.sleep(1500);
            failing.set(false);
            int failed = attempts.get();
            assertTrue(failed >= 2 && failed <= 30, "accepting was tried again, every 100 ms: " + failed + " attempts");
            long logged;
            synchronized (lines) {
                logged = lines.stream().filter(l -> l.startsWith("Accepting a connection failed: Too many open files")).count();
            }
            assertTrue(logged >= 1 && logged <= 2, "at most a line a second: " + lines);
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (clients.size() == 0 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertEquals(1, clients.size(), "the waiting client was taken once accepting worked again");
        } finally {
            listener.close();
        }
    }
}
