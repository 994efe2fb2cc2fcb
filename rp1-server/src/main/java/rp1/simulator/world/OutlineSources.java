package rp1.simulator.world;

import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;

/**
 * One copy of each distinct set of outlines (body coordinates) among a world's robots and their
 * contact sensors. A crowd is mostly of one design: its robots are then all placed from the same
 * arrays, which stay in the processor's cache, and {@link PlacedOutlines} needs a buffer per design
 * rather than one per robot. Outlines are the same only if every coordinate is the same to the bit,
 * so a robot placed from the shared copy is placed exactly as from its own. Each set's convex
 * {@link Hull} is made once as well.
 */
final class OutlineSources {
    private final Map<Key, double[][]> known = new HashMap<>();
    private final Map<double[][], Hull[]> hulls = new IdentityHashMap<>();

    /** The world's copy of {@code outlines}: the first equal set it was given. (Robots join rarely.) */
    synchronized double[][] intern(double[][] outlines) {
        return known.computeIfAbsent(new Key(outlines), Key::outlines);
    }

    /** The hulls of the polygons of {@code interned}, a copy {@link #intern} gave. */
    synchronized Hull[] hulls(double[][] interned) {
        return hulls.computeIfAbsent(interned, Hull::of);
    }

    /** Outlines compared by content, to the bit ({@link Arrays#deepEquals} compares doubles so). */
    private record Key(double[][] outlines) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && Arrays.deepEquals(outlines, k.outlines);
        }

        @Override
        public int hashCode() {
            return Arrays.deepHashCode(outlines);
        }
    }
}
