package rp1.simulator.config;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Which keys a server properties file may hold, so that a misspelt key is an error rather than a
 * silently ignored line ({@code maxSimulationTme=30} once ran a max-speed server for a million
 * simulated seconds). The table itself is {@link ServerConfig#KEYS}: a key is known because it is
 * declared there, and {@link PropertyReader} refuses to read one that is not.
 */
public final class PropertyKeys {
    private final Set<String> known;
    private final Map<String, String> unused;
    private final List<String> families;

    /**
     * @param known    keys the server reads
     * @param unused   keys RP1 0.60's files may hold that this server does not read, with why: accepted with a warning
     * @param families prefixes (ending in a dot) under which any key is accepted and left to whoever reads it
     */
    PropertyKeys(Set<String> known, Map<String, String> unused, List<String> families) {
        this.known = Set.copyOf(known);
        this.unused = Map.copyOf(unused);
        this.families = List.copyOf(families);
    }

    boolean isKnown(String key) {
        return known.contains(key) || families.stream().anyMatch(key::startsWith);
    }

    /**
     * Checks every key of {@code reader}'s table: an unknown key or an empty value is an error (the
     * first one in key order, so the message does not depend on the file's order); a key of RP1 0.60
     * this server does not use gives a warning.
     *
     * @param strict whether an unknown key is an error; if not, it is a warning too
     * @return the warnings, one line each, naming the source and the key
     */
    List<String> check(PropertyReader reader, boolean strict) throws ConfigException {
        List<String> warnings = new ArrayList<>();
        for (Map.Entry<String, String> e : reader.given().entrySet()) {
            String key = e.getKey();
            String value = e.getValue();
            if (unused.containsKey(key)) {
                warnings.add(reader.source() + ": " + key + "=" + value + ": ignored (" + unused.get(key) + ")");
            } else if (!isKnown(key)) {
                String problem = "unknown key; did you mean " + nearest(key) + "? (docs/properties.md lists them)";
                if (strict) {
                    throw reader.error(key, value, problem);
                }
                warnings.add(reader.source() + ": " + key + "=" + value + ": " + problem + "; ignored");
            } else if (PropertyReader.isEmpty(value)) {
                throw reader.error(key, value.trim(), "empty value (remove the line to get the default)");
            }
        }
        return warnings;
    }

    /** The known key closest to {@code key} in edit distance, ignoring letter case. */
    String nearest(String key) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String k : known.stream().sorted().toList()) {
            int d = distance(key.toLowerCase(Locale.ROOT), k.toLowerCase(Locale.ROOT));
            if (d < bestDistance) {
                best = k;
                bestDistance = d;
            }
        }
        return best;
    }

    /** Levenshtein distance: insertions, deletions and substitutions of one character each count 1. */
    public static int distance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitute = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitute, Math.min(previous[j], current[j - 1]) + 1);
            }
            int[] t = previous;
            previous = current;
            current = t;
        }
        return previous[b.length()];
    }
}
