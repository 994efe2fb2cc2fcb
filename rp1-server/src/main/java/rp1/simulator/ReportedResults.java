package rp1.simulator;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The results clients reported of their own ({@code RsClient.reportRunResult}), by client number, in
 * the order first reported; the last value of a name wins. Belongs to one simulation. Any thread.
 */
public final class ReportedResults {
    private final Map<Integer, Map<String, Double>> byClient = new HashMap<>();

    /** Records {@code value} as client {@code client}'s result {@code name}. */
    public synchronized void report(int client, String name, double value) {
        byClient.computeIfAbsent(client, c -> new LinkedHashMap<>()).put(name, value);
    }

    /** A copy of the results client {@code client} reported, in the order first reported; empty if none. */
    public synchronized Map<String, Double> of(int client) {
        return new LinkedHashMap<>(byClient.getOrDefault(client, Map.of()));
    }
}
