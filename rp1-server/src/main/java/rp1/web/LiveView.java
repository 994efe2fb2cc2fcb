package rp1.web;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;

import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;
import rp1.simulator.config.ServerConfig;

/**
 * The page of a running simulation, served over HTTP ({@code viewPort}, docs/properties.md): {@code /}
 * is the replay page holding the run so far, {@code /events} sends the rest as it happens
 * (server-sent events, one chunk of the page's encoding each, every tenth of a wall second that
 * brought something), and a press on the floor is posted to {@code /click} and becomes the view's
 * mouse-click input, as a click in the window does.
 *
 * <p>Watching changes nothing: the run is traced whether or not anybody watches, every browser gets
 * the same chunks from the one trace, and only the HTTP threads wait for slow browsers.
 */
public final class LiveView implements AutoCloseable {
    /** Wall milliseconds between chunks. */
    private static final long PERIOD_MILLIS = 100;
    /** Wall milliseconds without a chunk after which a comment line checks that the browser is still there. */
    private static final long KEEP_ALIVE_MILLIS = 10_000;
    private static final String EMPTY_CHUNK = "{\"t\":[],\"robots\":[],\"segs\":[],\"sel\":[],\"ev\":[]}";

    private final Simulation simulation;
    private final RunTrace trace;
    private final String plan;
    private final String title;
    private final HttpServer server;
    private final ExecutorService handlers;
    private final Thread pump;
    /** Every chunk so far, in order; its monitor is waited on by the browsers' streams. */
    private final List<String> chunks = new ArrayList<>();
    private volatile boolean closed;
    /** The simulation time the last chunk carried (only the pump and the closing thread publish). */
    private double lastNow = -1.0;

    private LiveView(Simulation simulation, HttpServer server, String title) {
        this.simulation = simulation;
        this.trace = RunTrace.attach(simulation);
        this.plan = trace.planJson();
        this.title = title;
        this.server = server;
        this.handlers = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "rp1-live-view-http");
            t.setDaemon(true);
            return t;
        });
        this.pump = new Thread(this::pumpChunks, "rp1-live-view");
        pump.setDaemon(true);
    }

    /**
     * Serves the page of {@code simulation} at {@code bindAddress}:{@code port} (0: any free port).
     * Call before the simulation runs, so the page holds the run from its start.
     *
     * @throws IOException if the port cannot be opened
     */
    public static LiveView start(Simulation simulation, String bindAddress, int port, String title) throws IOException {
        HttpServer server = HttpServer.create(new InetSocketAddress(bindAddress, port), 16);
        LiveView view = new LiveView(simulation, server, title);
        server.createContext("/", view::page);
        server.createContext("/events", view::events);
        server.createContext("/click", view::click);
        server.setExecutor(view.handlers);
        server.start();
        view.pump.start();
        return view;
    }

    /** The live view the settings ask for ({@code viewPort}), or nothing to close if they ask for none. */
    public static AutoCloseable startIfAsked(Simulation simulation, ServerConfig config, RsLogInterface log)
            throws IOException {
        if (config.viewPort == 0) {
            return () -> { };
        }
        LiveView view;
        try {
            view = start(simulation, config.bindAddress, config.viewPort, config.floorPlanFileName);
        } catch (IOException e) {
            throw new IOException("viewPort=" + config.viewPort + ": cannot serve the page on " + config.bindAddress + ":"
                    + config.viewPort + ": " + e.getMessage()
                    + (config.viewPort == config.port ? " (it is the simulator's own port; choose another)" : ""), e);
        }
        log.logIt("X", "The simulation can be watched at http://" + config.bindAddress + ":" + view.port() + "/");
        return view;
    }

    /** The port the page is served on. */
    public int port() {
        return server.getAddress().getPort();
    }

    private void pumpChunks() {
        while (!closed) {
            try {
                Thread.sleep(PERIOD_MILLIS);
            } catch (InterruptedException e) {
                return;
            }
            publish();
        }
    }

    /**
     * Makes what the trace gathered a chunk, with the simulation's time (which goes on while nothing
     * changes, and which the page's clock follows), as the window's clock reads it.
     */
    private void publish() {
        String chunk = trace.drain();
        double now = simulation.getSimTime();
        if (!chunk.equals(EMPTY_CHUNK) || now != lastNow) {
            lastNow = now;
            String timed = chunk.substring(0, chunk.length() - 1) + ",\"now\":" + new Json().value(now) + "}";
            synchronized (chunks) {
                chunks.add(timed);
                chunks.notifyAll();
            }
        }
    }

    private List<String> chunksFrom(int from) {
        synchronized (chunks) {
            return new ArrayList<>(chunks.subList(Math.min(from, chunks.size()), chunks.size()));
        }
    }

    private void page(HttpExchange x) throws IOException {
        try (x) {
            if (!x.getRequestURI().getPath().equals("/")) {
                x.sendResponseHeaders(404, -1);
                return;
            }
            byte[] body = Page.live(title, plan, chunksFrom(0)).getBytes(StandardCharsets.UTF_8);
            x.getResponseHeaders().set("Content-Type", "text/html; charset=utf-8");
            x.getResponseHeaders().set("Cache-Control", "no-store");
            x.sendResponseHeaders(200, body.length);
            x.getResponseBody().write(body);
        }
    }

    /**
     * One browser's stream: the chunks after those its page holds, then each new one as it comes, and
     * at the run's end an {@code end} event. Each chunk carries its number as its id (the count of
     * chunks up to it), so that a browser that reconnects, as browsers do by themselves after a
     * dropped connection, says with {@code Last-Event-ID} how far it got and is sent the rest, not
     * again everything since its page loaded (the page adds positions up, so a chunk twice moved the
     * robots). After the {@code end} event the page stops asking.
     */
    private void events(HttpExchange x) throws IOException {
        try (x) {
            String seen = x.getRequestHeaders().getFirst("Last-Event-ID");
            int next = Math.max(0, Integer.parseInt(seen != null ? seen.trim() : query(x).getOrDefault("from", "0")));
            x.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
            x.getResponseHeaders().set("Cache-Control", "no-store");
            x.sendResponseHeaders(200, 0);
            OutputStream out = x.getResponseBody();
            boolean last = false;
            while (!last) {
                // Read before taking the chunks: everything published before closing is then sent.
                last = closed;
                List<String> fresh = awaitChunks(next);
                StringBuilder text = new StringBuilder(fresh.isEmpty() && !last ? ":\n\n" : "");
                for (String c : fresh) {
                    next++;
                    text.append("id: ").append(next).append("\ndata: ").append(c).append("\n\n");
                }
                if (last) {
                    text.append("event: end\ndata: \n\n");
                }
                out.write(text.toString().getBytes(StandardCharsets.UTF_8));
                out.flush();
            }
        } catch (NumberFormatException | InterruptedException e) {
            // A malformed request or a closing view: the stream simply ends.
        }
    }

    private List<String> awaitChunks(int from) throws InterruptedException {
        synchronized (chunks) {
            if (chunks.size() <= from && !closed) {
                chunks.wait(KEEP_ALIVE_MILLIS);
            }
        }
        return chunksFrom(from);
    }

    private void click(HttpExchange x) throws IOException {
        try (x) {
            if (!x.getRequestMethod().equals("POST")) {
                x.sendResponseHeaders(405, -1);
                return;
            }
            if (!fromThisPage(x)) {
                x.sendResponseHeaders(403, -1);
                return;
            }
            Map<String, String> form;
            try (InputStream in = x.getRequestBody()) {
                form = form(new String(in.readNBytes(1024), StandardCharsets.UTF_8));
            }
            try {
                int button = Integer.parseInt(form.get("button"));
                int clicks = Integer.parseInt(form.get("clicks"));
                double wx = Double.parseDouble(form.get("x"));
                double wy = Double.parseDouble(form.get("y"));
                if (button < 1 || button > 3 || clicks < 1 || !Double.isFinite(wx) || !Double.isFinite(wy)) {
                    throw new NumberFormatException("out of range");
                }
                simulation.mouseClick(button, clicks, wx, wy);
                x.sendResponseHeaders(204, -1);
            } catch (NumberFormatException | NullPointerException e) {
                x.sendResponseHeaders(400, -1);
            }
        }
    }

    /**
     * A browser names the page a request comes from ({@code Origin}): a click is taken only from this
     * server's own page, so a page on some other site that the user happens to open cannot steer the
     * robots. Clients that are not browsers send no {@code Origin} and are taken as they are.
     */
    private static boolean fromThisPage(HttpExchange x) {
        String origin = x.getRequestHeaders().getFirst("Origin");
        String host = x.getRequestHeaders().getFirst("Host");
        return origin == null || (host != null && origin.equals("http://" + host));
    }

    private static Map<String, String> query(HttpExchange x) {
        String q = x.getRequestURI().getRawQuery();
        return form(q == null ? "" : q);
    }

    private static Map<String, String> form(String text) {
        Map<String, String> values = new HashMap<>();
        for (String pair : text.split("&")) {
            int eq = pair.indexOf('=');
            if (eq > 0) {
                values.put(URLDecoder.decode(pair.substring(0, eq), StandardCharsets.UTF_8),
                        URLDecoder.decode(pair.substring(eq + 1), StandardCharsets.UTF_8));
            }
        }
        return values;
    }

    /**
     * Stops serving: the trace stops, the browsers' streams end with what was gathered up to here
     * (they are given a second to take it), and the port closes.
     */
    @Override
    public void close() {
        pump.interrupt();
        trace.close();
        synchronized (chunks) {
            publish();
            closed = true;
            chunks.notifyAll();
        }
        server.stop(1);
        handlers.shutdownNow();
    }
}
