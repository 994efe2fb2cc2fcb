package rp1.simulator.world;

import java.awt.Color;

/**
 * One unbroken piece of a paint trail: up to {@link #CAPACITY} points in single precision, with the
 * colour and width it was painted in. Points are only ever appended, so an observer that read the
 * point count may read that many points while the simulation keeps painting.
 */
public final class TrailSegment {
    /** Points per segment; a full segment is continued in a new one. */
    public static final int CAPACITY = 1024;

    private final float[] xy = new float[2 * CAPACITY];
    private volatile int count;
    private final Color color;
    private final double width;

    TrailSegment(Color color, double width) {
        this.color = color;
        this.width = width;
    }

    /** The colour the trail is drawn in (the first of the painter's colours). */
    public Color getColor() {
        return color;
    }

    /** The trail width in metres. */
    public double getWidth() {
        return width;
    }

    /** The number of points recorded so far. */
    public int getCount() {
        return count;
    }

    public double getX(int i) {
        return xy[2 * i];
    }

    public double getY(int i) {
        return xy[2 * i + 1];
    }

    boolean isFull() {
        return count == CAPACITY;
    }

    /** Appends a point if it is at least {@code minSpacing} from the last one (the first always is). */
    void append(double x, double y, double minSpacing) {
        int n = count;
        if (n > 0) {
            double dx = x - xy[2 * n - 2];
            double dy = y - xy[2 * n - 1];
            if (dx * dx + dy * dy < minSpacing * minSpacing) {
                return;
            }
        }
        xy[2 * n] = (float) x;
        xy[2 * n + 1] = (float) y;
        count = n + 1;
    }
}
