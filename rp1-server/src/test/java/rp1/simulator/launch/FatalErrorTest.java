package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A server that runs out of memory ends, with a message and {@link ExitStatus#FATAL_ERROR}, instead
 * of staying up holding its port and serving nobody. The server runs in a child JVM with a small
 * heap, its timeout budget lifted so that one client's flood of timeouts can exhaust it.
 */
@Timeout(120)
class FatalErrorTest {
    @TempDir
    Path dir;

    /** A port the child may listen on: the server takes 1025..32767, below Linux's ephemeral range. */
    private static int freePort() throws IOException {
        for (int attempt = 0; attempt < 100; attempt++) {
            int port = ThreadLocalRandom.current().nextInt(20000, 32768);
            try {
                // Binding is the whole check: the port is given back at once.
                new ServerSocket(port).close();
                return port;
            } catch (IOException inUse) {
                // Try another.
            }
        }
        throw new IOException("no free port in 20000..32767");
    }

    private static void awaitListening(Process p, Path log) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!(Files.exists(log) && Files.readString(log).contains("Now accepting connections"))) {
            assertTrue(p.isAlive() && System.nanoTime() < deadline, "the server started");
            Thread.sleep(20);
        }
    }

    @Test
    void runningOutOfMemoryEndsTheServerWithStatus70() throws Exception {
        int port = freePort();
        TestServer.write(dir, "port=" + port, "simulationSpeed=1", "waitForClients=0",
                "clientTimeoutBudget=" + Integer.MAX_VALUE);
        File output = dir.resolve("output.txt").toFile();
        Process p = new ProcessBuilder(JavaCommand.of(List.of("-Xmx32m", "-XX:+UseSerialGC"), "rp1.Server",
                "-p", TestServer.PROPERTIES))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(output).start();
        try {
            awaitListening(p, dir.resolve(TestServer.LOG));
            RawClient flood = RawClient.connected(port);
            // A server that stops reading would block a write for ever: the flood has a thread of its own.
            Thread flooding = new Thread(() -> {
                try {
                    for (int i = 0; ; i++) {
                        flood.request(0);
                        flood.out.writeDouble(1.0e6);
                        flood.out.writeInt(i);
                    }
                } catch (IOException hungUp) {
                    // The server went away, or the test closed the socket.
                }
            }, "flood");
            flooding.setDaemon(true);
            flooding.start();
            boolean ended = p.waitFor(60, TimeUnit.SECONDS);
            flood.close();
            assertTrue(ended, "the server ended");
            String out = new String(Files.readAllBytes(output.toPath()), StandardCharsets.UTF_8);
            assertEquals(ExitStatus.FATAL_ERROR, p.exitValue(), out);
            assertTrue(out.contains("rp1.Server: java.lang.OutOfMemoryError"), out);
            assertTrue(out.contains("the server stops (exit status 70)"), out);
        } finally {
            p.destroyForcibly();
        }
    }
}
