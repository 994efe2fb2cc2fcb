package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import rp1.rossum.RsMotion;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;

/**
 * The robots on the floor by place: each robot's box (a square about its position, as wide as its
 * reach, grown by how far it can move before it is next evaluated) in a uniform grid, updated when the
 * robot is evaluated, placed or removed. "Which robots could be near this one in the coming interval"
 * then costs about the robots near it, not all of them.
 */
final class RobotIndex {
    private static final double CELL = 1.0;
    private static final int MAX_CELLS = 1 << 16;

    private final Grid grid;
    private Robot[] byNumber = new Robot[16];
    private int[] found = new int[32];
    private int foundCount;

    /** An index over {@code area} (robots outside it still work, less selectively). */
    RobotIndex(RsRectangle area) {
        RsRectangle a = new RsRectangle(area);
        if (!a.isPopulated() || a.width <= 0 || a.height <= 0) {
            a = new RsRectangle(-50, -50, 100, 100);
        }
        grid = new Grid(a, CELL, MAX_CELLS);
    }

    /**
     * Files the robot under the box where it can be from {@code time} for {@code horizon} seconds
     * (robots without shapes are not filed: nothing can touch or see them).
     */
    void put(Robot r, double time, double horizon) {
        remove(r);
        if (r.shapes().isEmpty()) {
            return;
        }
        int n = r.getNumber();
        if (n >= byNumber.length) {
            byNumber = Arrays.copyOf(byNumber, Math.max(n + 1, byNumber.length * 2));
        }
        byNumber[n] = r;
        double[] box = r.indexBox();
        RsTransform pose = r.poseAt(time);
        double x = pose.m13;
        double y = pose.m23;
        double grow = r.shapes().reach() + speedBound(r) * horizon + RobotContacts.SAMPLE_SPACING;
        box[0] = x - grow;
        box[1] = y - grow;
        box[2] = x + grow;
        box[3] = y + grow;
        grid.insert(n, box[0], box[1], box[2], box[3]);
        r.setIndexed(true);
    }

    /** Takes the robot out. */
    void remove(Robot r) {
        if (r.isIndexed()) {
            double[] box = r.indexBox();
            grid.remove(r.getNumber(), box[0], box[1], box[2], box[3]);
            byNumber[r.getNumber()] = null;
            r.setIndexed(false);
        }
    }

    /** Upper bound of the speed of any point of the robot's shapes under its current motion. */
    static double speedBound(Robot r) {
        RsMotion m = r.motion();
        if (!r.isMoving() || m == null) {
            return 0.0;
        }
        return Math.abs(m.getVelocity()) + Math.abs(m.getTurnRate()) * r.shapes().reach();
    }

    /** The robots whose boxes overlap [x0, x1] x [y0, y1], in joining order. */
    List<Robot> near(double x0, double y0, double x1, double y1) {
        foundCount = 0;
        grid.query(x0, y0, x1, y1, this::found);
        Arrays.sort(found, 0, foundCount);
        List<Robot> out = new ArrayList<>(foundCount);
        for (int i = 0; i < foundCount; i++) {
            double[] box = byNumber[found[i]].indexBox();
            if (box[0] <= x1 && x0 <= box[2] && box[1] <= y1 && y0 <= box[3]) {
                out.add(byNumber[found[i]]);
            }
        }
        return out;
    }

    private void found(int id) {
        if (foundCount == found.length) {
            found = Arrays.copyOf(found, foundCount * 2);
        }
        found[foundCount++] = id;
    }
}
