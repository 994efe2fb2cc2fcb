package rp1.simulator.world;

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

    private final RsWall[] walls;
    private final Grid grid;

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
        grid = Grid.forIndex(area);
        for (int i = 0; i < walls.length; i++) {
            RsRectangle b = walls[i].getBounds();
            grid.insert(i, b.x, b.y, b.x + b.width, b.y + b.height);
        }
    }

    /** The walls whose boxes come near the box [x0, x1] x [y0, y1] (every wall of a small plan). */
    RsWall[] near(double x0, double y0, double x1, double y1) {
        return grid == null ? walls : collected(grid.collect(x0, y0, x1, y1));
    }

    /** The walls within {@code radius} of the segment (every wall of a small plan). */
    RsWall[] alongSegment(double x0, double y0, double x1, double y1, double radius) {
        return grid == null ? walls : collected(grid.collectAlongSegment(x0, y0, x1, y1, radius));
    }

    private RsWall[] collected(int count) {
        RsWall[] out = new RsWall[count];
        for (int i = 0; i < count; i++) {
            out[i] = walls[grid.hit(i)];
        }
        return out;
    }
}
