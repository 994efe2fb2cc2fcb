package rp1.simulator;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * The names of the run's parameters ({@code param.NAME}) its loaded clients asked for
 * ({@code RsClient.getRunParameter}), in the order first asked, whether the run has them or not: a
 * sweep that varies a parameter no robot asks for can say so, instead of giving rows that differ only
 * by a name mistyped. Belongs to one simulation. Any thread.
 */
public final class AskedParameters {
    private final Set<String> names = new LinkedHashSet<>();

    /** A client asked for parameter {@code name}. */
    public synchronized void asked(String name) {
        names.add(name);
    }

    /** The names asked for so far, in the order first asked. */
    public synchronized List<String> names() {
        return List.copyOf(names);
    }
}
