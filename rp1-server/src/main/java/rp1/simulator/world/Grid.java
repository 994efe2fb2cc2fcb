package rp1.simulator.world;

import java.util.Arrays;

import rp1.rossum.RsRectangle;

/**
 * A uniform grid of square cells over an area, each cell listing the items (numbered 0..n-1) whose
 * bounding boxes overlap it, so that "what is near this box" costs about the items near it rather than
 * all of them. Items and queries outside the area are clamped to its border cells: still correct, only
 * less selective. A query reports each item once, in ascending item order within a cell sweep; callers
 * that need a deterministic order sort or use the item numbers.
 */
final class Grid {
    /** The cell size the indexes ask for, metres: about a robot's neighbourhood. */
    private static final double INDEX_CELL = 1.0;
    /** The most cells an index's grid has, whatever its area. */
    private static final int INDEX_MAX_CELLS = 1 << 16;
    /** How many items a cell keeps in {@link #slots}: a robot's neighbourhood in metre cells holds one or two. */
    private static final int IN_PLACE = 4;
    /** Up to this many items found are sorted by insertion. */
    private static final int SMALL_SORT = 24;

    private final double minX;
    private final double minY;
    private final double cell;
    private final int cols;
    private final int rows;
    /**
     * Each cell's first {@link #IN_PLACE} items, cell after cell: a query's cells along a row lie side
     * by side in memory. With ten thousand robots an array per cell, somewhere in the heap, was a
     * cache miss per cell looked at.
     */
    private final int[] slots;
    /** Per cell, the items after its first {@link #IN_PLACE} (null until a cell has more). */
    private final int[][] overflow;
    /** Per cell, how many items it lists. */
    private final int[] counts;
    private int[] marks = new int[16];
    private int stamp;
    /** What the last {@link #collect} found; one buffer, reused by every query. */
    private int[] hits = new int[32];
    private int hitCount;
    private final Visitor collector = this::addHit;

    /**
     * A grid over {@code area} with cells of {@code cellSize} metres, or larger ones where that would
     * make more than {@code maxCells} cells in all: however large or long the area, the grid's memory
     * stays bounded.
     *
     * @throws IllegalArgumentException if the area is not finite
     */
    Grid(RsRectangle area, double cellSize, int maxCells) {
        if (!(Double.isFinite(area.x) && Double.isFinite(area.y) && Double.isFinite(area.width)
                && Double.isFinite(area.height))) {
            throw new IllegalArgumentException("a grid needs a finite area, not " + area);
        }
        double width = Math.max(area.width, 1e-6);
        double height = Math.max(area.height, 1e-6);
        double spread = width * height;
        double even = Math.sqrt(Double.isFinite(spread) ? spread / maxCells : width / maxCells * height);
        double size = Math.max(Math.max(cellSize, even), Math.max(width, height) / maxCells);
        while (cellsAcross(width, size) * cellsAcross(height, size) > maxCells) {
            size *= 1.25;
        }
        this.minX = area.x;
        this.minY = area.y;
        this.cell = size;
        this.cols = (int) cellsAcross(width, size);
        this.rows = (int) cellsAcross(height, size);
        this.slots = new int[cols * rows * IN_PLACE];
        this.overflow = new int[cols * rows][];
        this.counts = new int[cols * rows];
    }

    /** The grid the wall and robot indexes file their items in: metre cells, at most 65536 of them. */
    static Grid forIndex(RsRectangle area) {
        return new Grid(area, INDEX_CELL, INDEX_MAX_CELLS);
    }

    /** Cells of {@code size} needed to cover {@code length}, as a double so that no product overflows. */
    private static double cellsAcross(double length, double size) {
        return Math.max(1.0, Math.ceil(length / size));
    }

    /** How many cells the grid has. */
    int cellCount() {
        return counts.length;
    }

    private int col(double x) {
        return cellOf((x - minX) / cell, cols);
    }

    private int row(double y) {
        return cellOf((y - minY) / cell, rows);
    }

    /**
     * The cell {@code at} cells from the grid's edge lies in, clamped to 0..count-1 (NaN to 0): the
     * floor of {@code at} without {@code Math.floor}, which a sweep's quickly compiled code calls as a
     * method on every move of a robot (a cast truncates, and truncating is flooring from 0 up).
     */
    private static int cellOf(double at, int count) {
        if (!(at >= 1.0)) {
            return 0;
        }
        return at >= count - 1 ? count - 1 : (int) at;
    }

    /** Adds item {@code id} over the box [x0, x1] x [y0, y1]. */
    void insert(int id, double x0, double y0, double x1, double y1) {
        int c0 = col(x0);
        int c1 = col(x1);
        int r0 = row(y0);
        int r1 = row(y1);
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                add(r * cols + c, id);
            }
        }
        if (id >= marks.length) {
            marks = Arrays.copyOf(marks, Math.max(id + 1, marks.length * 2));
        }
    }

    /** Removes item {@code id}, which was inserted over the box [x0, x1] x [y0, y1]. */
    void remove(int id, double x0, double y0, double x1, double y1) {
        int c0 = col(x0);
        int c1 = col(x1);
        int r0 = row(y0);
        int r1 = row(y1);
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                int index = r * cols + c;
                int n = counts[index];
                for (int i = 0; i < n; i++) {
                    if (item(index, i) == id) {
                        for (int j = i; j + 1 < n; j++) {
                            setItem(index, j, item(index, j + 1));
                        }
                        counts[index] = n - 1;
                        break;
                    }
                }
            }
        }
    }

    /**
     * Moves item {@code id} from the box it was inserted over to [x0, x1] x [y0, y1]. Most moves stay
     * within the same cells (a robot's box moves a few centimetres per evaluation in metre cells), and
     * then the cells are left as they are.
     */
    void move(int id, double oldX0, double oldY0, double oldX1, double oldY1, double x0, double y0, double x1,
              double y1) {
        if (col(oldX0) == col(x0) && col(oldX1) == col(x1) && row(oldY0) == row(y0) && row(oldY1) == row(y1)) {
            return;
        }
        remove(id, oldX0, oldY0, oldX1, oldY1);
        insert(id, x0, y0, x1, y1);
    }

    private void add(int index, int id) {
        int n = counts[index];
        if (n >= IN_PLACE) {
            int[] more = overflow[index];
            int k = n - IN_PLACE;
            if (more == null || k == more.length) {
                overflow[index] = more == null ? new int[IN_PLACE] : Arrays.copyOf(more, 2 * k);
            }
        }
        setItem(index, n, id);
        counts[index] = n + 1;
    }

    /** The {@code i}th item of cell {@code index} (i below its count). */
    private int item(int index, int i) {
        return i < IN_PLACE ? slots[index * IN_PLACE + i] : overflow[index][i - IN_PLACE];
    }

    private void setItem(int index, int i, int id) {
        if (i < IN_PLACE) {
            slots[index * IN_PLACE + i] = id;
        } else {
            overflow[index][i - IN_PLACE] = id;
        }
    }

    /** What a query found. */
    @FunctionalInterface
    interface Visitor {
        void visit(int id);
    }

    /** Tells {@code visitor} about every item whose cells overlap the box [x0, x1] x [y0, y1], once each. */
    void query(double x0, double y0, double x1, double y1, Visitor visitor) {
        int mark = nextStamp();
        int c0 = col(x0);
        int c1 = col(x1);
        int r0 = row(y0);
        int r1 = row(y1);
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                visitCell(r * cols + c, mark, visitor);
            }
        }
    }

    /**
     * Tells {@code visitor} about every item in the cells within {@code radius} of the segment from
     * (x0, y0) to (x1, y1), once each: the items a body of that reach could meet moving along it.
     */
    void querySegment(double x0, double y0, double x1, double y1, double radius, Visitor visitor) {
        int mark = nextStamp();
        int c0 = col(Math.min(x0, x1) - radius);
        int c1 = col(Math.max(x0, x1) + radius);
        int r0 = row(Math.min(y0, y1) - radius);
        int r1 = row(Math.max(y0, y1) + radius);
        double reach = radius + cell * Math.sqrt(0.5);
        // A long segment's box covers a great many cells that are nowhere near it (a drive "for ever"
        // crosses the whole plan): each row looks only at the columns near the part of the segment
        // within reach of the row, a cell wider on every side than rounding could ever need, and the
        // test below decides as before.
        double wide = reach + cell;
        for (int r = r0; r <= r1; r++) {
            double cy = minY + (r + 0.5) * cell;
            int from = c0;
            int to = c1;
            double lo;
            double hi;
            if (y0 == y1) {
                if (Math.abs(y0 - cy) > wide) {
                    continue;
                }
                lo = Math.min(x0, x1);
                hi = Math.max(x0, x1);
            } else {
                double ta = (cy - wide - y0) / (y1 - y0);
                double tb = (cy + wide - y0) / (y1 - y0);
                double t0 = Math.max(0.0, Math.min(ta, tb));
                double t1 = Math.min(1.0, Math.max(ta, tb));
                if (t0 > t1) {
                    continue;
                }
                double xa = x0 + t0 * (x1 - x0);
                double xb = x0 + t1 * (x1 - x0);
                lo = Math.min(xa, xb);
                hi = Math.max(xa, xb);
            }
            if (Double.isFinite(lo - wide) && Double.isFinite(hi + wide)) {
                from = Math.max(c0, col(lo - wide));
                to = Math.min(c1, col(hi + wide));
            }
            for (int c = from; c <= to; c++) {
                // An empty cell (most of a wall index's) is passed over before its distance is worked out.
                int index = r * cols + c;
                if (counts[index] == 0) {
                    continue;
                }
                double cx = minX + (c + 0.5) * cell;
                if (Outlines.squaredToSegment(cx, cy, x0, y0, x1, y1) <= reach * reach) {
                    visitCell(index, mark, visitor);
                }
            }
        }
    }

    /**
     * Collects the items {@link #query} would visit, in ascending item order; returns how many, each
     * then read with {@link #hit}. The answer is valid until the next query.
     */
    int collect(double x0, double y0, double x1, double y1) {
        hitCount = 0;
        query(x0, y0, x1, y1, collector);
        return sortedHits();
    }

    /** Like {@link #collect}, for the items {@link #querySegment} would visit. */
    int collectAlongSegment(double x0, double y0, double x1, double y1, double radius) {
        hitCount = 0;
        querySegment(x0, y0, x1, y1, radius, collector);
        return sortedHits();
    }

    /** The {@code i}th item the last collection found. */
    int hit(int i) {
        return hits[i];
    }

    private void addHit(int id) {
        if (hitCount == hits.length) {
            hits = Arrays.copyOf(hits, hitCount * 2);
        }
        hits[hitCount++] = id;
    }

    private int sortedHits() {
        // A query mostly finds a handful of items: those are sorted in place by insertion, without the
        // library sort's set-up for large arrays.
        if (hitCount > SMALL_SORT) {
            Arrays.sort(hits, 0, hitCount);
            return hitCount;
        }
        int[] h = hits;
        for (int i = 1; i < hitCount; i++) {
            int v = h[i];
            int j = i - 1;
            while (j >= 0 && h[j] > v) {
                h[j + 1] = h[j];
                j--;
            }
            h[j + 1] = v;
        }
        return hitCount;
    }

    private void visitCell(int index, int mark, Visitor visitor) {
        int n = counts[index];
        int base = index * IN_PLACE;
        for (int i = 0, inPlace = Math.min(n, IN_PLACE); i < inPlace; i++) {
            visitItem(slots[base + i], mark, visitor);
        }
        if (n > IN_PLACE) {
            int[] more = overflow[index];
            for (int i = 0; i < n - IN_PLACE; i++) {
                visitItem(more[i], mark, visitor);
            }
        }
    }

    private void visitItem(int id, int mark, Visitor visitor) {
        if (marks[id] != mark) {
            marks[id] = mark;
            visitor.visit(id);
        }
    }

    private int nextStamp() {
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(marks, 0);
            stamp = 1;
        }
        return stamp;
    }
}
