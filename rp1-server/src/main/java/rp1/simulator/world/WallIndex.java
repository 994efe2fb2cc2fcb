package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsRectangle;
import rp1.rossum.RsWall;

/**
 * The plan's walls and obstacles by place: the walls near a box, or along a path, in plan order (the
 * order matters where two walls tie, as it did for RP1 0.60's searches over all of them). A plan with
 * few walls is not indexed: the answer is then always every wall.
 */
final class WallIndex {
    /** Plans with at most this many walls are searched whole. */
    private static final int SMALL = 24;
    private static final double CELL = 1.0;
    private static final int MAX_CELLS = 1 << 16;

    private final RsWall[] walls;
    private final Grid grid;
    private int[] found = new int[32];
    private int foundCount;

    WallIndex(RsWall[] walls) {
        this.walls = walls;
        if (walls.length <= SMALL) {
            grid = null;
            return;
        }
        RsRectangle area = new RsRectangle();
        for (RsWall w : walls) {
            area.union(w.getBounds());
        }
        grid = new Grid(area, CELL, MAX_CELLS);
        for (int i = 0; i < walls.length; i++) {
            RsRectangle b = walls[i].getBounds();
            grid.insert(i, b.x, b.y, b.x + b.width, b.y + b.height);
        }
    }

    /** The walls whose boxes come near the box [x0, x1] x [y0, y1] (every wall of a small plan). */
    RsWall[] near(double x0, double y0, double x1, double y1) {
        if (grid == null) {
            return walls;
        }
        foundCount = 0;
        grid.query(x0, y0, x1, y1, this::found);
        return collected();
    }

    /** The walls within {@code radius} of the segment (every wall of a small plan). */
    RsWall[] alongSegment(double x0, double y0, double x1, double y1, double radius) {
        if (grid == null) {
            return walls;
        }
        foundCount = 0;
        grid.querySegment(x0, y0, x1, y1, radius, this::found);
        return collected();
    }

    private void found(int id) {
        if (foundCount == found.length) {
            found = Arrays.copyOf(found, foundCount * 2);
        }
        found[foundCount++] = id;
    }

    private RsWall[] collected() {
        Arrays.sort(found, 0, foundCount);
        RsWall[] out = new RsWall[foundCount];
        for (int i = 0; i < foundCount; i++) {
            out[i] = walls[found[i]];
        }
        return out;
    }
}
