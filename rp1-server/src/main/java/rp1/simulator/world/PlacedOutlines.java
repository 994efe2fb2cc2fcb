package rp1.simulator.world;

import java.util.IdentityHashMap;
import java.util.Map;

import rp1.rossum.RsTransform;

/**
 * Robots' outlines placed at poses for the contact search, in buffers the search owns. It holds two
 * robots at a time, the pair being searched, and keeps each placement while the same robot is asked
 * for at the same pose, bit for bit (a robot at rest is asked for at every sample of its pair). The
 * buffers are one per design of outlines ({@link OutlineSources}), not one per robot: every placement
 * in a crowd writes to the same few arrays, which stay in the processor's cache, where a buffer per
 * robot meant bringing in a thousand robots' worth of arrays.
 */
final class PlacedOutlines {
    private final Slot first = new Slot();
    private final Slot second = new Slot();
    /** The slot asked for last: the other one is taken for a robot neither holds. */
    private Slot recent = second;
    /** Buffers for contact sensors' outlines, by design; placed anew at every call. */
    private final Map<double[][], Outlines> sensors = new IdentityHashMap<>();

    /**
     * The robot's shapes placed at {@code pose}: valid until outlines are asked for two other robots,
     * or for this one at another pose.
     */
    Outlines of(Robot r, RsTransform pose) {
        Slot s = first.robot == r ? first : (second.robot == r ? second : (recent == first ? second : first));
        recent = s;
        if (s.robot != r || !s.pose.is(pose)) {
            s.robot = r;
            s.pose.set(pose);
            s.placed = s.buffer(r.shapes().outlines()).place(pose);
        }
        return s.placed;
    }

    /**
     * A contact sensor's outline (as its one polygon, from the robot's shapes) placed at {@code pose}:
     * valid until the next call.
     */
    Outlines sensor(double[][] outline, RsTransform pose) {
        return sensors.computeIfAbsent(outline, Outlines::roomFor).place(pose);
    }

    /** One robot's placement, and a buffer per design placed in it so far. */
    private static final class Slot {
        Robot robot;
        final LastPose pose = new LastPose();
        Outlines placed;
        private final Map<double[][], Outlines> buffers = new IdentityHashMap<>();

        Outlines buffer(double[][] source) {
            if (placed != null && placed.source() == source) {
                return placed;
            }
            return buffers.computeIfAbsent(source, Outlines::roomFor);
        }
    }
}
