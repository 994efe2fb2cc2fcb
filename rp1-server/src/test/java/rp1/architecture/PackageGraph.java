package rp1.architecture;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Which package uses which, and the groups of packages that use one another in a ring: a package of
 * such a group cannot be understood, tested or moved without the others. Found with Tarjan's
 * strongly connected components over the edges, in name order so that a failure reads the same each
 * time.
 */
final class PackageGraph {
    private final Map<String, Set<String>> uses = new TreeMap<>();
    private final Map<String, Integer> index = new TreeMap<>();
    private final Map<String, Integer> low = new TreeMap<>();
    private final List<String> stack = new ArrayList<>();
    private final List<Set<String>> rings = new ArrayList<>();
    private int next;

    /** {@code from} uses {@code to}; a package using itself is no edge. */
    void add(String from, String to) {
        uses.computeIfAbsent(from, k -> new TreeSet<>());
        uses.computeIfAbsent(to, k -> new TreeSet<>());
        if (!from.equals(to)) {
            uses.get(from).add(to);
        }
    }

    /** The package a qualified name lies in: its parts up to the first that begins with a capital. */
    static String packageOf(String qualifiedName) {
        String[] parts = qualifiedName.split("\\.");
        StringBuilder b = new StringBuilder(parts[0]);
        for (int i = 1; i < parts.length && !parts[i].isEmpty() && Character.isLowerCase(parts[i].charAt(0)); i++) {
            b.append('.').append(parts[i]);
        }
        return b.toString();
    }

    /** Every group of two or more packages that use one another, each in name order. */
    List<Set<String>> rings() {
        index.clear();
        low.clear();
        stack.clear();
        rings.clear();
        next = 0;
        for (String p : uses.keySet()) {
            if (!index.containsKey(p)) {
                visit(p);
            }
        }
        return new ArrayList<>(rings);
    }

    private void visit(String p) {
        index.put(p, next);
        low.put(p, next);
        next++;
        stack.add(p);
        for (String q : uses.get(p)) {
            if (!index.containsKey(q)) {
                visit(q);
                low.put(p, Math.min(low.get(p), low.get(q)));
            } else if (stack.contains(q)) {
                low.put(p, Math.min(low.get(p), index.get(q)));
            }
        }
        if (low.get(p).equals(index.get(p))) {
            Set<String> ring = new TreeSet<>();
            String q;
            do {
                q = stack.remove(stack.size() - 1);
                ring.add(q);
            } while (!q.equals(p));
            if (ring.size() > 1) {
                rings.add(ring);
            }
        }
    }
}
