package rp1.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.HttpURLConnection;
import java.net.ServerSocket;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.event.RsMouseClickEvent;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;

/**
 * {@code viewPort}: the page of a running simulation, its stream of chunks to several browsers at
 * once, and clicks posted from it; none of the watching changes the run.
 */
@Timeout(120)
class LiveViewTest {
    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    /**
     * A lockstep run of the gated wanderer, its gate opened once {@code watchers} browsers watch.
     *
     * @return the run's event log
     */
    private static String run(Path dir, int watchers, List<Watcher> started) throws Exception {
        int port = freePort();
        Runs.properties(dir, 20.0, "eventLogFileName=run.events", "dlcName=" + GatedWanderer.class.getName(),
                watchers > 0 ? "viewPort=" + port : "viewPort=0");
        GatedWanderer.close();
        RunningServer server = Runs.start(dir, LaunchOptions.defaults());
        for (int i = 0; i < watchers; i++) {
            started.add(Watcher.start(port));
        }
        for (Watcher w : started) {
            assertTrue(w.streaming.await(10, TimeUnit.SECONDS), "a watcher is connected");
        }
        GatedWanderer.open();
        assertTrue(server.awaitExit(60, TimeUnit.SECONDS).isPresent(), "the run ends");
        return Files.readString(dir.resolve("run.events"), StandardCharsets.UTF_8);
    }

    @Test
    void aRunWatchedByThreeBrowsersSendsTheEventsOfOneWatchedByNone(@TempDir Path alone, @TempDir Path watched)
            throws Exception {
        String unwatched = run(alone, 0, new ArrayList<>());
        List<Watcher> watchers = new ArrayList<>();
        String seen = run(watched, 3, watchers);
        assertTrue(unwatched.contains(" MotionHalted "), unwatched);
        assertEquals(unwatched, seen);
        for (Watcher w : watchers) {
            w.join(10_000);
            assertTrue(w.page.contains("\"live\":1"), "the page is the live one");
            assertTrue(w.frames.get() > 100, "a watcher got only " + w.frames.get() + " frames");
            assertEquals(watchers.get(0).frames.get(), w.frames.get(), "every watcher gets every frame");
        }
    }

    /** A page that cannot be served is refused at start-up naming viewPort, and why. */
    @Test
    void aViewPortTakenByTheSimulatorItselfIsRefusedNamingIt(@TempDir Path dir) throws Exception {
        int port = freePort();
        Runs.properties(dir, 5.0, "simulationSpeed=1", "enableNetworkClients=true", "port=" + port, "viewPort=" + port);
        rp1.simulator.launch.StartupException e = assertThrows(rp1.simulator.launch.StartupException.class,
                () -> Runs.start(dir, LaunchOptions.defaults()));
        assertTrue(e.getMessage().startsWith("cannot open the view: viewPort=" + port + ": cannot serve the page on "),
                e.getMessage());
        assertTrue(e.getMessage().endsWith("(it is the simulator's own port; choose another)"), e.getMessage());
    }

    @Test
    void viewPortIsOffByDefaultAndAPortOtherwise() throws Exception {
        Properties p = new Properties();
        p.setProperty("floorPlanFileName", "WhiteRoom.txt");
        assertEquals(0, ServerConfig.from(p, "t.ini", null).viewPort, "off by default");
        p.setProperty("viewPort", "8080");
        assertEquals(8080, ServerConfig.from(p, "t.ini", null).viewPort);
        p.setProperty("viewPort", "http");
        ConfigException e = assertThrows(ConfigException.class, () -> ServerConfig.from(p, "t.ini", null));
        assertTrue(e.getMessage().contains("viewPort"), e.getMessage());
    }

    @Test
    void aClickPostedFromThePageReachesTheRobotsAsAClickInTheWindowDoes(@TempDir Path dir) throws Exception {
        int port = freePort();
        Runs.properties(dir, 60.0, "simulationSpeed=1", "viewPort=" + port);
        RunningServer server = Runs.start(dir, LaunchOptions.defaults());
        List<RsMouseClickEvent> clicks = new CopyOnWriteArrayList<>();
        server.getSimulation().addEventListener((session, event, delivered) -> {
            if (event instanceof RsMouseClickEvent e && delivered) {
                clicks.add(e);
            }
        });
        try {
            assertEquals(400, post(port, "button=1&clicks=1&x=oops&y=2"), "a malformed click is refused");
            assertEquals(403, postFrom("http://elsewhere.example", port, "button=1&clicks=1&x=1&y=1"),
                    "a click from another site's page is refused");
            assertEquals(204, post(port, "button=1&clicks=2&x=1.25&y=0.75"));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (clicks.isEmpty() && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
        } finally {
            server.stop();
        }
        assertEquals(1, clicks.size(), "one click reached the robot");
        RsMouseClickEvent e = clicks.get(0);
        assertEquals(List.of(1, 2, 1.25, 0.75), List.of(e.button, e.clickCount, e.x, e.y));
    }

    /**
     * A browser whose connection dropped asks again saying how far it got (Last-Event-ID), and is sent
     * the chunks after that one, not again all those since its page loaded: the page adds positions
     * up, so a chunk sent twice moved the robots. At the run's end the stream says so.
     */
    @Test
    void aBrowserThatReconnectsIsSentOnlyTheChunksItHasNotHad(@TempDir Path dir) throws Exception {
        int port = freePort();
        Runs.properties(dir, 60.0, "simulationSpeed=1", "viewPort=" + port);
        RunningServer server = Runs.start(dir, LaunchOptions.defaults());
        List<String> lines = new ArrayList<>();
        try {
            HttpURLConnection first = (HttpURLConnection) new URL("http://127.0.0.1:" + port + "/events?from=0")
                    .openConnection();
            try (BufferedReader in = new BufferedReader(new InputStreamReader(first.getInputStream(), StandardCharsets.UTF_8))) {
                List<String> ids = new ArrayList<>();
                for (String line = in.readLine(); ids.size() < 4; line = in.readLine()) {
                    if (line.startsWith("id: ")) {
                        ids.add(line);
                    }
                }
                assertEquals(List.of("id: 1", "id: 2", "id: 3", "id: 4"), ids, "each chunk is numbered");
            }
            HttpURLConnection again = (HttpURLConnection) new URL("http://127.0.0.1:" + port + "/events?from=0")
                    .openConnection();
            again.setRequestProperty("Last-Event-ID", "3");
            BufferedReader in = new BufferedReader(new InputStreamReader(again.getInputStream(), StandardCharsets.UTF_8));
            String line = in.readLine();
            while (!line.startsWith("id: ")) {
                line = in.readLine();
            }
            assertEquals("id: 4", line, "the stream goes on after the last chunk the browser had");
            server.stop();
            for (; line != null; line = in.readLine()) {
                lines.add(line);
            }
        } finally {
            server.stop();
        }
        assertTrue(lines.contains("event: end"), "the run's end is told, so that the page stops asking: " + lines);
    }

    static int post(int port, String form) throws IOException {
        HttpURLConnection c = (HttpURLConnection) new URL("http://127.0.0.1:" + port + "/click").openConnection();
        c.setRequestMethod("POST");
        c.setDoOutput(true);
        try (OutputStream out = c.getOutputStream()) {
            out.write(form.getBytes(StandardCharsets.UTF_8));
        }
        return c.getResponseCode();
    }

    /** A click posted by a page of {@code origin}, as a browser names it. */
    static int postFrom(String origin, int port, String form) throws IOException, InterruptedException {
        java.net.http.HttpRequest request = java.net.http.HttpRequest.newBuilder(
                        java.net.URI.create("http://127.0.0.1:" + port + "/click"))
                .header("Origin", origin)
                .header("Content-Type", "application/x-www-form-urlencoded")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString(form)).build();
        return java.net.http.HttpClient.newHttpClient()
                .send(request, java.net.http.HttpResponse.BodyHandlers.discarding()).statusCode();
    }

    /** A browser, as far as the server can tell: it loads the page, then reads the stream until it ends. */
    static final class Watcher extends Thread {
        final AtomicInteger frames = new AtomicInteger();
        final CountDownLatch streaming = new CountDownLatch(1);
        volatile String page = "";
        private final int port;

        private Watcher(int port) {
            this.port = port;
            setDaemon(true);
        }

        static Watcher start(int port) {
            Watcher w = new Watcher(port);
            w.start();
            return w;
        }

        @Override
        public void run() {
            try {
                page = read(new URL("http://127.0.0.1:" + port + "/"));
                frames.addAndGet(count(page));
                HttpURLConnection c = (HttpURLConnection) new URL("http://127.0.0.1:" + port + "/events?from="
                        + chunksIn(page)).openConnection();
                try (BufferedReader in = new BufferedReader(new InputStreamReader(c.getInputStream(), StandardCharsets.UTF_8))) {
                    streaming.countDown();
                    for (String line = in.readLine(); line != null; line = in.readLine()) {
                        if (line.startsWith("data: ")) {
                            frames.addAndGet(count(line));
                        }
                    }
                }
            } catch (IOException e) {
                // The server stopped: the stream ends.
            }
        }

        private static String read(URL url) throws IOException {
            try (var in = url.openStream()) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
        }

        /** The frames in a text holding chunks: the entries of their time lists. */
        private static int count(String text) {
            int n = 0;
            for (int i = text.indexOf("\"t\":["); i >= 0; i = text.indexOf("\"t\":[", i + 1)) {
                int end = text.indexOf(']', i);
                String list = text.substring(i + 5, end);
                n += list.isEmpty() ? 0 : list.split(",").length;
            }
            return n;
        }

        private static int chunksIn(String page) {
            int n = 0;
            for (int i = page.indexOf("\"t\":["); i >= 0; i = page.indexOf("\"t\":[", i + 1)) {
                n++;
            }
            return n;
        }
    }
}
