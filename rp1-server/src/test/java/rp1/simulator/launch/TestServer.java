package rp1.simulator.launch;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;

/**
 * Servers for tests, started in-process from a properties file written to a temporary directory, on a
 * free port, headless, logging to {@code server.log} there. The directory also holds {@code arena.txt}:
 * a 20 m square room with placements p1 .. p50 on a 1.5 m by 2 m grid, all facing east.
 */
final class TestServer {
    static final String PROPERTIES = "test.ini";
    static final String LOG = "server.log";
    static final int PLACEMENTS = 50;

    private TestServer() {
    }

    /** Writes the properties (defaults first; later lines override) and the arena into {@code dir}. */
    static Path write(Path dir, String... lines) {
        StringBuilder props = new StringBuilder();
        props.append("floorPlanFileName=arena.txt\nenableGUI=false\nlogToFile=true\nlogFileName=")
                .append(LOG).append("\nconnectTimeout=2\n");
        for (String line : lines) {
            props.append(line).append('\n');
        }
        try {
            Files.write(dir.resolve("arena.txt"), arena().getBytes(StandardCharsets.UTF_8));
            return Files.write(dir.resolve(PROPERTIES), props.toString().getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Starts a server from {@code lines} on a free port. */
    static RunningServer start(Path dir, String... lines) throws StartupException {
        write(dir, lines);
        return ServerLauncher.start(new String[] {"-p", PROPERTIES}, dir, LaunchOptions.defaults().withPort(0));
    }

    static String placementName(int i) {
        return "p" + i;
    }

    static double placementX(int i) {
        return 2.0 + 1.5 * ((i - 1) % 10);
    }

    static double placementY(int i) {
        return 2.0 + 2.0 * ((i - 1) / 10);
    }

    private static String arena() {
        StringBuilder b = new StringBuilder("caption: \"arena\";\n");
        b.append("wall s { geometry: 0, 0, 20, 0, 0.05; }\n");
        b.append("wall e { geometry: 20, 0, 20, 20, 0.05; }\n");
        b.append("wall n { geometry: 20, 20, 0, 20, 0.05; }\n");
        b.append("wall w { geometry: 0, 20, 0, 0, 0.05; }\n");
        for (int i = 1; i <= PLACEMENTS; i++) {
            b.append(String.format(Locale.ROOT, "placement %s { geometry: %.2f, %.2f, 0, 0.2; }%n",
                    placementName(i), placementX(i), placementY(i)));
        }
        return b.toString();
    }

    /** The server log so far. */
    static String log(Path dir) {
        try {
            return new String(Files.readAllBytes(dir.resolve(LOG)), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Waits (at most 10 s) until the log contains {@code fragment}; returns the log. */
    static String awaitLog(Path dir, String fragment) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (true) {
            String log = log(dir);
            if (log.contains(fragment)) {
                return log;
            }
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the log does not say \"" + fragment + "\" within 10 s:\n" + log);
            }
            Thread.sleep(10);
        }
    }

    /** The body the test clients send: a disc of radius 0.15 m named {@code name}. */
    static RsBody roundBody(String name) {
        RsBody body = new RsBody(name);
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        return body;
    }
}
