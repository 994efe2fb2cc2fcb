package rp1.simulator.scenario;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The event transcripts of the scenarios run while collection is on: for each test, every client's
 * events before the latest time the test waited for (the part no thread can change), as text, in
 * the order the clients connected. {@link DeliveryEquivalenceTest} runs the
 * scenario tests with pipes and with direct delivery and compares.
 */
final class Transcripts {
    private static final Map<String, String> collected = new LinkedHashMap<>();
    private static String currentTest;

    private Transcripts() {
    }

    /** Collection is on (for the test named {@code test}) until {@link #take()}. */
    static synchronized void begin(String test) {
        currentTest = test;
    }

    /** Adds the transcripts of a scenario that just ended, if collection is on. */
    static synchronized void record(List<ScenarioClient> clients) {
        if (currentTest == null) {
            return;
        }
        double seen = Double.NEGATIVE_INFINITY;
        for (ScenarioClient c : clients) {
            seen = Math.max(seen, c.lastAwaited());
        }
        StringBuilder b = new StringBuilder("until ").append(seen).append('\n');
        for (int i = 0; i < clients.size(); i++) {
            b.append("client ").append(i + 1).append(":\n").append(clients.get(i).transcriptBefore(seen));
        }
        collected.merge(currentTest, b.toString(), String::concat);
    }

    /** What was collected, by test; collection stops. */
    static synchronized Map<String, String> take() {
        Map<String, String> out = new LinkedHashMap<>(collected);
        collected.clear();
        currentTest = null;
        return out;
    }
}
