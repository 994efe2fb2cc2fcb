package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsTransform;

/**
 * A pose remembered bit for bit, so that what was computed for it can be kept and a pose asked for
 * again recognised: the same robot's pose is asked for by every neighbour in a step.
 */
final class LastPose {
    private final RsTransform last = new RsTransform();

    /** Bit for bit the same pose (as {@link Arrays#equals(double[], double[])} compares). */
    boolean is(RsTransform pose) {
        return same(pose.m11, last.m11) && same(pose.m12, last.m12) && same(pose.m13, last.m13)
                && same(pose.m21, last.m21) && same(pose.m22, last.m22) && same(pose.m23, last.m23);
    }

    void set(RsTransform pose) {
        last.copy(pose);
    }

    private static boolean same(double a, double b) {
        return Double.doubleToLongBits(a) == Double.doubleToLongBits(b);
    }
}
