package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;

/**
 * The robots on the floor by place: each robot's box (a square about its position, as wide as its
 * reach, grown by how far it can move before it is next evaluated) in a uniform grid, updated when the
 * robot is evaluated, placed or removed. "Which robots could be near this one in the coming interval"
 * then costs about the robots near it, not all of them. The index keeps the robots and their boxes by
 * robot number (numbers are dense: the order of joining).
 */
final class RobotIndex {
    private final Grid grid;
    /** The robot filed under each number, or null. */
    private Robot[] byNumber = new Robot[16];
    /** Each filed robot's box at 4 × its number: x0, y0, x1, y1. */
    private double[] boxes = new double[4 * 16];
    /** A robot's pose while it is filed (only its position is read). */
    private final RsTransform scratch = new RsTransform();

    /** An index over {@code area} (robots outside it still work, less selectively). */
    RobotIndex(RsRectangle area) {
        RsRectangle a = new RsRectangle(area);
        if (!a.isPopulated() || a.width <= 0 || a.height <= 0) {
            a = new RsRectangle(-50, -50, 100, 100);
        }
        grid = Grid.forIndex(a);
    }

    /**
     * Files the robot under the box where it can be from {@code time} for {@code horizon} seconds
     * (robots without shapes are not filed: nothing can touch or see them).
     */
    void put(Robot r, double time, double horizon) {
        if (r.shapes().isEmpty()) {
            remove(r);
            return;
        }
        int n = r.getNumber();
        if (n >= byNumber.length) {
            byNumber = Arrays.copyOf(byNumber, Math.max(n + 1, byNumber.length * 2));
            boxes = Arrays.copyOf(boxes, 4 * byNumber.length);
        }
        RsTransform pose = r.poseAt(time, scratch);
        double x = pose.m13;
        double y = pose.m23;
        double grow = r.shapes().reach() + r.speedBound() * horizon + RobotContacts.SAMPLE_SPACING;
        int b = 4 * n;
        if (byNumber[n] == null) {
            grid.insert(n, x - grow, y - grow, x + grow, y + grow);
        } else {
            grid.move(n, boxes[b], boxes[b + 1], boxes[b + 2], boxes[b + 3], x - grow, y - grow, x + grow, y + grow);
        }
        byNumber[n] = r;
        boxes[b] = x - grow;
        boxes[b + 1] = y - grow;
        boxes[b + 2] = x + grow;
        boxes[b + 3] = y + grow;
    }

    /** Takes the robot out. */
    void remove(Robot r) {
        int n = r.getNumber();
        if (n < byNumber.length && byNumber[n] != null) {
            int b = 4 * n;
            grid.remove(n, boxes[b], boxes[b + 1], boxes[b + 2], boxes[b + 3]);
            byNumber[n] = null;
        }
    }

    /**
     * The robots whose boxes overlap [x0, x1] x [y0, y1], in joining order, other than {@code self} (if
     * not null), less those whose box's circle {@code reach} (if not null) turns down. A robot lies
     * within its box, so its box tells whether something of it could be within reach without reading
     * the robot itself (with ten thousand robots, reading a robot's motion is a cache miss or more, and
     * a sensor's ray passes near few of the robots around). A robot asking what is near it finds
     * itself in nearly every query, so it is passed over by number.
     */
    List<Robot> near(double x0, double y0, double x1, double y1, Robot self, Reach reach) {
        int count = grid.collect(x0, y0, x1, y1);
        int skip = self == null ? -1 : self.getNumber();
        // Most queries keep no robot at all (a sensor's sight in a crowd: 94 in 100), so the list is
        // made for the first robot kept.
        List<Robot> out = List.of();
        for (int i = 0; i < count; i++) {
            int n = grid.hit(i);
            int b = 4 * n;
            if (n != skip && boxes[b] <= x1 && x0 <= boxes[b + 2] && boxes[b + 1] <= y1 && y0 <= boxes[b + 3]
                    && (reach == null || reachesBox(reach, b))) {
                if (out.isEmpty()) {
                    out = new ArrayList<>(count - i);
                }
                out.add(byNumber[n]);
            }
        }
        return out;
    }

    /**
     * Whether {@code reach} takes in the circle through the corners of the box at {@code b}, grown by
     * a slack far above the rounding of its centre and radius.
     */
    private boolean reachesBox(Reach reach, int b) {
        double hw = 0.5 * (boxes[b + 2] - boxes[b]);
        double hh = 0.5 * (boxes[b + 3] - boxes[b + 1]);
        double r = Math.sqrt(hw * hw + hh * hh);
        return reach.within(boxes[b] + hw, boxes[b + 1] + hh, r + 1.0e-9 * (1.0 + r));
    }

    /** A test of what could be within reach of something. */
    @FunctionalInterface
    interface Reach {
        /** Whether something within {@code radius} of (x, y) could be within reach. */
        boolean within(double x, double y, double radius);
    }
}
