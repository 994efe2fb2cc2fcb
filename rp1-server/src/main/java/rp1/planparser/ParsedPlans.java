package rp1.planparser;

import java.io.IOException;
import java.io.StringReader;
import java.util.HashMap;
import java.util.Map;

import rp1.rossum.RsPlan;

/**
 * Floor plans parsed once for many runs: each run gets a {@link RsPlan#copy() copy} of the plan
 * parsed from the same file name and text, since a run changes its own plan (it selects targets, sets
 * the random source). A sweep's runs in one process share one of these: parsing the plan was a sixth
 * of a bumper run's work on its job thread, its start and its report (docs/performance.md). A plan that fails to parse is not kept,
 * so every run that names it reports the error. The images of a map plan are read with its first
 * parse: all runs of the sweep see the same map. Safe for use by several threads.
 */
public final class ParsedPlans {
    /** The text each plan was parsed from, by file name, with the plan, which no run is given. */
    private final Map<String, Parsed> plans = new HashMap<>();

    private record Parsed(String text, RsPlan plan) {
    }

    /**
     * A copy of the plan {@code text} read from {@code fileName} parses to, parsed on the first call
     * with that name and text (and again when the text under a name changes).
     *
     * @throws RsParsingException if the plan is malformed
     * @throws IOException if a map's image cannot be read
     */
    public synchronized RsPlan copyOf(String text, String fileName) throws RsParsingException, IOException {
        Parsed known = plans.get(fileName);
        if (known == null || !known.text().equals(text)) {
            known = new Parsed(text, RsPlanParser.parse(new StringReader(text), fileName));
            plans.put(fileName, known);
        }
        return known.plan().copy();
    }
}
