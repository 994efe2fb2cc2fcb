package rp1.simulator.world;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The robots due for evaluation, earliest first, those due at the same time in joining order (by
 * number). A crowd's robots fall due in a few groups per modelling step, and a robot is often moved to
 * an earlier time (stopped by a contact): kept by time, each time's robots a set of numbers, moving
 * one costs a lookup instead of a heap's linear search and the group comes out in order without a
 * chain of comparisons per robot. A time's set is used again for a later time once its robots are
 * taken: a crowd's group times are new at every step, and a set grown anew each time for a thousand
 * robots was a tenth of what the motion task allocated.
 */
final class DueRobots {
    private final TreeMap<Double, BitSet> byTime = new TreeMap<>();
    /** Emptied sets, to be used again. */
    private final ArrayDeque<BitSet> spare = new ArrayDeque<>();
    /** By robot number: when the robot is due (NaN: not due), and the robot. */
    private double[] due = new double[0];
    private Robot[] robots = new Robot[0];

    /** Whether the robot is due. */
    boolean isDue(Robot r) {
        int n = r.getNumber();
        return n < due.length && !Double.isNaN(due[n]);
    }

    /** When the robot is due; only for a robot that is. */
    double dueTime(Robot r) {
        return due[r.getNumber()];
    }

    /** The robot is due at {@code time} (and no longer when it was before). */
    void put(Robot r, double time) {
        remove(r);
        int n = r.getNumber();
        if (n >= due.length) {
            int old = due.length;
            due = Arrays.copyOf(due, Math.max(n + 1, 2 * old));
            robots = Arrays.copyOf(robots, due.length);
            Arrays.fill(due, old, due.length, Double.NaN);
        }
        due[n] = time;
        robots[n] = r;
        Double key = time;
        BitSet numbers = byTime.get(key);
        if (numbers == null) {
            numbers = spare.isEmpty() ? new BitSet(due.length) : spare.pop();
            byTime.put(key, numbers);
        }
        numbers.set(n);
    }

    /** The robot is not due any more. */
    void remove(Robot r) {
        if (!isDue(r)) {
            return;
        }
        int n = r.getNumber();
        BitSet numbers = byTime.get(due[n]);
        numbers.clear(n);
        if (numbers.isEmpty()) {
            byTime.remove(due[n]);
            spare.push(numbers);
        }
        due[n] = Double.NaN;
        robots[n] = null;
    }

    boolean isEmpty() {
        return byTime.isEmpty();
    }

    /** The earliest time a robot is due; only when one is. */
    double first() {
        return byTime.firstKey();
    }

    /** Takes the robots due by {@code time} out, adding them to {@code into} by time, then number. */
    void takeDueBy(double time, List<Robot> into) {
        while (!byTime.isEmpty() && byTime.firstKey() <= time) {
            Map.Entry<Double, BitSet> first = byTime.pollFirstEntry();
            BitSet numbers = first.getValue();
            for (int n = numbers.nextSetBit(0); n >= 0; n = numbers.nextSetBit(n + 1)) {
                into.add(robots[n]);
                due[n] = Double.NaN;
                robots[n] = null;
            }
            numbers.clear();
            spare.push(numbers);
        }
    }
}
