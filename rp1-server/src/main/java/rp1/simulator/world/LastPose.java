package rp1.simulator.world;

import rp1.rossum.RsTransform;

/**
 * A pose remembered bit for bit, so that what was computed for it can be kept and a pose asked for
 * again recognised: the same robot's pose is asked for by every neighbour in a step. It is itself a
 * transform, holding the pose's numbers, rather than referring to one: with ten thousand robots each
 * object a robot's step reads is a wait for memory.
 */
final class LastPose extends RsTransform {
    private static final long serialVersionUID = 1L;

    /** Whether a pose was remembered (a new one holds the identity, which is no pose asked about yet). */
    private boolean known;

    /** Bit for bit the same pose as the one remembered; none before the first {@link #set}. */
    boolean is(RsTransform pose) {
        return known && pose.sameBits(this);
    }

    void set(RsTransform pose) {
        copy(pose);
        known = true;
    }
}
