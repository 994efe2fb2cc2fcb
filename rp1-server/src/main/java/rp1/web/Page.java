package rp1.web;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * The page that shows a run (docs/recording.md, "The replay page"): one HTML file with its script
 * and styles inline, nothing fetched from elsewhere, and the run's data in a JSON script element:
 * the plan, then chunks of frames and events that the script decodes in order. A replay page holds
 * the whole run; a live page holds what had happened when it was asked for and takes the rest from
 * its server as it comes.
 */
public final class Page {
    private static final String TEMPLATE = template();

    private Page() {
    }

    /**
     * The page of a finished run.
     *
     * @param title  what the browser's tab says
     * @param plan   {@link RunTrace#planJson()}
     * @param chunks {@link RunTrace#drain()}, in order
     * @param end    the simulated time the run ended at
     */
    public static String replay(String title, String plan, List<String> chunks, double end) {
        return fill(title, plan, chunks, end, false);
    }

    /** The page of a running simulation, holding {@code chunks} so far; it asks its server for the rest. */
    static String live(String title, String plan, List<String> chunks) {
        return fill(title, plan, chunks, 0.0, true);
    }

    private static String fill(String title, String plan, List<String> chunks, double end, boolean live) {
        Json data = new Json().beginObject().key("live").value(live).key("end").value(end).key("header").raw(plan)
                .key("chunks").beginArray();
        for (String c : chunks) {
            data.raw(c);
        }
        String json = data.endArray().endObject().toString();
        return TEMPLATE.replace("/*RP1-TITLE*/", html(title)).replace("/*RP1-DATA*/", json);
    }

    private static String html(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    private static String template() {
        try (InputStream in = Page.class.getResourceAsStream("page.html")) {
            if (in == null) {
                throw new IllegalStateException("rp1/web/page.html is missing from the class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
