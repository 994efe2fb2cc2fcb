package rp1demo.adapter;

import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1demo.navigation.Pose;

/** Poses from the events that carry one, and what a target sensor's sighting tells about the target. */
public final class Poses {
    private Poses() {
    }

    public static Pose of(RsPlacementEvent e) {
        return new Pose(e.x, e.y, e.orientation);
    }

    public static Pose of(RsPositionEvent e) {
        return new Pose(e.x, e.y, e.orientation);
    }

    public static Pose of(RsMotionHaltedEvent e) {
        return new Pose(e.x, e.y, e.orientation);
    }

    /**
     * Where a detected target is in the world, from the sensor's position and line of sight that the
     * event carries (docs/protocol.md section 7.5). A real robot would have to work this out from its
     * own idea of where it is.
     *
     * @return {x, y} in metres
     */
    public static double[] targetPosition(RsTargetSensorEvent e) {
        return new double[] {
            e.x + e.xDetection * e.ux - e.yDetection * e.uy,
            e.y + e.xDetection * e.uy + e.yDetection * e.ux};
    }
}
