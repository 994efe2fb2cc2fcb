package rp1.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import rp1.simulator.launch.JavaCommand;

/**
 * A freshly started server answering its first clients: {@code java rp1.Server} started as a new
 * process, then, once its port accepts, 20 clients one after another (connect, handshake, body,
 * placement event), timed from this already warm client process. The first client is timed on its
 * own too.
 */
final class ColdStart {
    private static final int PORT = 17758;

    private ColdStart() {
    }

    static void run(int servers) throws Exception {
        Connecting.warmUp();
        for (int i = 0; i < servers; i++) {
            Path dir = Files.createTempDirectory("rp1-cold");
            Files.write(dir.resolve("cold.ini"), String.join("\n", "floorPlanFileName=WhiteRoom.txt", "enableGUI=false",
                    "port=" + PORT, "randomSeed=1", "").getBytes(
                    StandardCharsets.UTF_8));
            List<String> command = JavaCommand.of(JavaCommand.simulatorOptions(), "rp1.Server", "-p", "cold.ini");
            long launched = System.nanoTime();
            Process server = new ProcessBuilder(command).directory(dir.toFile())
                    .redirectOutput(dir.resolve("out.txt").toFile()).redirectErrorStream(true).start();
            try {
                awaitPort();
                double ready = (System.nanoTime() - launched) * 1e-6;
                double first = Connecting.placeInARow(PORT, 1);
                double nineteen = Connecting.placeInARow(PORT, 19);
                double next = Connecting.placeInARow(PORT, 20);
                System.out.printf(Locale.ROOT, "fresh server %d (its port open %.0f ms after launch): 20 clients one after"
                        + " another %.1f ms, the first %.1f ms; the next 20 %.1f ms%n", i + 1, ready, first + nineteen,
                        first, next);
            } finally {
                server.destroy();
                server.waitFor();
            }
        }
    }

    private static void awaitPort() throws IOException, InterruptedException {
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (true) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", PORT), 100);
                return;
            } catch (IOException e) {
                if (System.nanoTime() > deadline) {
                    throw e;
                }
                Thread.sleep(5);
            }
        }
    }
}
