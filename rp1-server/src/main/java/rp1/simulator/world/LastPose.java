package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsTransform;

/**
 * A pose remembered bit for bit, so that what was computed for it can be kept and a pose asked for
 * again recognised: the same robot's pose is asked for by every neighbour in a step. The numbers are
 * fields of this object, not of a transform it refers to: with ten thousand robots each object a
 * robot's step reads is a wait for memory.
 */
final class LastPose {
    private boolean known;
    private double m11;
    private double m12;
    private double m13;
    private double m21;
    private double m22;
    private double m23;

    /** Bit for bit the same pose (as {@link Arrays#equals(double[], double[])} compares); none before the first {@link #set}. */
    boolean is(RsTransform pose) {
        return known && same(pose.m11, m11) && same(pose.m12, m12) && same(pose.m13, m13)
                && same(pose.m21, m21) && same(pose.m22, m22) && same(pose.m23, m23);
    }

    void set(RsTransform pose) {
        m11 = pose.m11;
        m12 = pose.m12;
        m13 = pose.m13;
        m21 = pose.m21;
        m22 = pose.m22;
        m23 = pose.m23;
        known = true;
    }

    private static boolean same(double a, double b) {
        return Double.doubleToLongBits(a) == Double.doubleToLongBits(b);
    }
}
