package rp1.simulator.snapshot;

import java.awt.Color;

import rp1.simulator.world.TrailSegment;

/**
 * The first {@code count} points of a paint-trail segment. Segments only ever grow, so these points
 * never change however long the simulation goes on painting.
 *
 * @param segment the live segment
 * @param count   the number of points it had when the snapshot was taken
 */
public record TrailSnapshot(TrailSegment segment, int count) {

    /** Checks that the count is one the segment has reached. */
    public TrailSnapshot {
        if (count < 0 || count > segment.getCount()) {
            throw new IllegalArgumentException("count must be in [0, " + segment.getCount() + "], got " + count);
        }
    }

    /** The segment as it is now. */
    public static TrailSnapshot of(TrailSegment segment) {
        return new TrailSnapshot(segment, segment.getCount());
    }

    /** Point {@code i}, world metres. */
    public double x(int i) {
        return segment.getX(checked(i));
    }

    /** Point {@code i}, world metres. */
    public double y(int i) {
        return segment.getY(checked(i));
    }

    /** The colour the trail is painted in. */
    public Color color() {
        return segment.getColor();
    }

    /** The trail width, metres. */
    public double width() {
        return segment.getWidth();
    }

    private int checked(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("point " + i + " of " + count);
        }
        return i;
    }
}
