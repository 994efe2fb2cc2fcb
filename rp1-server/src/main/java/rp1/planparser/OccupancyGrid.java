package rp1.planparser;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * The occupied cells of an occupancy-grid map, row-major with the image's top row first, and their
 * cover by as few axis-aligned rectangles as a row-then-column merge finds: each row is cut into runs
 * of occupied cells, and a run continues the rectangle above it when it spans exactly the same
 * columns. The same merge is tried along columns, and the smaller cover kept, so a map of long
 * vertical corridors does not come out as one rectangle per row.
 */
final class OccupancyGrid {
    /** Cells an image may have: 64 Mi (8192 × 8192), far beyond a building's map at 5 cm. */
    static final long MAX_CELLS = 1L << 26;

    /**
     * A rectangle of occupied cells, in cells: columns {@code column} to {@code column + width},
     * rows {@code row} to {@code row + height} (rows counted from the image's top).
     */
    record Cells(int column, int row, int width, int height) {
    }

    private final int width;
    private final int height;
    private final BitSet occupied;

    OccupancyGrid(int width, int height) {
        this.width = width;
        this.height = height;
        this.occupied = new BitSet(width * height);
    }

    int width() {
        return width;
    }

    int height() {
        return height;
    }

    /** Marks the cell at {@code column}, {@code row} (row 0 is the image's top) occupied. */
    void occupy(int column, int row) {
        occupied.set(row * width + column);
    }

    boolean isOccupied(int column, int row) {
        return occupied.get(row * width + column);
    }

    /** How many cells are occupied. */
    int occupiedCount() {
        return occupied.cardinality();
    }

    /** Rectangles covering exactly the occupied cells, without overlap; the smaller of the two merges. */
    List<Cells> rectangles() {
        List<Cells> byRows = merge(occupied, width, height);
        List<Cells> byColumns = new ArrayList<>();
        for (Cells c : merge(transposed(), height, width)) {
            byColumns.add(new Cells(c.row(), c.column(), c.height(), c.width()));
        }
        return byColumns.size() < byRows.size() ? byColumns : byRows;
    }

    private BitSet transposed() {
        BitSet t = new BitSet(width * height);
        for (int i = occupied.nextSetBit(0); i >= 0; i = occupied.nextSetBit(i + 1)) {
            t.set((i % width) * height + i / width);
        }
        return t;
    }

    /**
     * The row merge over {@code bits} ({@code lines} lines of {@code length} cells): a rectangle stays
     * open while each following line has a run with exactly its first and last column.
     */
    private static List<Cells> merge(BitSet bits, int length, int lines) {
        List<Cells> done = new ArrayList<>();
        List<int[]> open = new ArrayList<>();
        for (int line = 0; line < lines; line++) {
            List<int[]> next = new ArrayList<>();
            int i = 0;
            int start = line * length;
            int end = start + length;
            for (int a = bits.nextSetBit(start); a >= 0 && a < end; a = bits.nextSetBit(a)) {
                int b = Math.min(bits.nextClearBit(a), end);
                int from = a - start;
                int to = b - start;
                while (i < open.size() && open.get(i)[0] < from) {
                    close(open.get(i++), line, done);
                }
                if (i < open.size() && open.get(i)[0] == from && open.get(i)[1] == to) {
                    next.add(open.get(i++));
                } else {
                    next.add(new int[] {from, to, line});
                }
                a = b;
            }
            while (i < open.size()) {
                close(open.get(i++), line, done);
            }
            open = next;
        }
        for (int[] run : open) {
            close(run, lines, done);
        }
        return done;
    }

    private static void close(int[] run, int line, List<Cells> done) {
        done.add(new Cells(run[0], run[2], run[1] - run[0], line - run[2]));
    }
}
