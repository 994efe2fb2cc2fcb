package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsRectangle;

/** The spatial grid keeps its memory bounded whatever the area, and finds items wherever they are. */
class GridTest {
    private static final int MAX_CELLS = 1 << 16;

    private static List<Integer> query(Grid grid, double x0, double y0, double x1, double y1) {
        List<Integer> found = new ArrayList<>();
        grid.query(x0, y0, x1, y1, found::add);
        return found;
    }

    private static List<Integer> alongSegment(Grid grid, double x0, double y0, double x1, double y1, double r) {
        List<Integer> found = new ArrayList<>();
        grid.querySegment(x0, y0, x1, y1, r, found::add);
        return found;
    }

    /**
     * Items moved a little or far, in and out of the area, are found exactly where a grid that took
     * them out and put them in anew finds them.
     */
    @Test
    void aMovedItemIsFoundWhereItWasPutAnew() {
        double side = 20.0;
        Grid moved = new Grid(new RsRectangle(0, 0, side, side), 1.0, MAX_CELLS);
        Grid anew = new Grid(new RsRectangle(0, 0, side, side), 1.0, MAX_CELLS);
        java.util.Random random = new java.util.Random(9);
        double[][] boxes = new double[60][];
        for (int id = 0; id < boxes.length; id++) {
            boxes[id] = box(random, random.nextDouble() * side, random.nextDouble() * side);
            moved.insert(id, boxes[id][0], boxes[id][1], boxes[id][2], boxes[id][3]);
            anew.insert(id, boxes[id][0], boxes[id][1], boxes[id][2], boxes[id][3]);
        }
        for (int step = 0; step < 20_000; step++) {
            int id = random.nextInt(boxes.length);
            double[] old = boxes[id];
            // Mostly a robot's few centimetres, now and then a jump (a placement), sometimes off the area.
            double jump = step % 50 == 0 ? side : 0.05;
            double[] box = box(random, old[0] + (random.nextDouble() - 0.5) * jump,
                    old[1] + (random.nextDouble() - 0.5) * jump);
            moved.move(id, old[0], old[1], old[2], old[3], box[0], box[1], box[2], box[3]);
            anew.remove(id, old[0], old[1], old[2], old[3]);
            anew.insert(id, box[0], box[1], box[2], box[3]);
            boxes[id] = box;
            double qx = random.nextDouble() * side * 1.2 - 0.1 * side;
            double qy = random.nextDouble() * side * 1.2 - 0.1 * side;
            double w = random.nextDouble() * 3;
            List<Integer> a = query(moved, qx, qy, qx + w, qy + w);
            List<Integer> b = query(anew, qx, qy, qx + w, qy + w);
            a.sort(null);
            b.sort(null);
            assertEquals(b, a, "step " + step);
        }
    }

    /**
     * A crowd in a few cells (cells listing a dozen items and more, items coming and going) is visited
     * exactly as lists per cell would visit it: cell after cell along each row, each cell's items in
     * the order they came, each item once.
     */
    @Test
    void crowdedCellsAreVisitedAsListsPerCellWouldVisitThem() {
        double side = 4.0;
        Grid grid = new Grid(new RsRectangle(0, 0, side, side), 1.0, MAX_CELLS);
        List<List<Integer>> lists = new ArrayList<>();
        for (int c = 0; c < 16; c++) {
            lists.add(new ArrayList<>());
        }
        java.util.Random random = new java.util.Random(17);
        double[][] boxes = new double[80][];
        for (int step = 0; step < 20_000; step++) {
            int id = random.nextInt(boxes.length);
            if (boxes[id] != null) {
                double[] old = boxes[id];
                grid.remove(id, old[0], old[1], old[2], old[3]);
                for (int cell : cellsOf(old)) {
                    lists.get(cell).remove(Integer.valueOf(id));
                }
            }
            double[] box = box(random, random.nextDouble() * side, random.nextDouble() * side);
            grid.insert(id, box[0], box[1], box[2], box[3]);
            for (int cell : cellsOf(box)) {
                lists.get(cell).add(id);
            }
            boxes[id] = box;
            double qx = random.nextDouble() * side;
            double qy = random.nextDouble() * side;
            double w = random.nextDouble() * 2;
            List<Integer> expected = new ArrayList<>();
            for (int cell : cellsOf(new double[] {qx, qy, qx + w, qy + w})) {
                for (int item : lists.get(cell)) {
                    if (!expected.contains(item)) {
                        expected.add(item);
                    }
                }
            }
            assertEquals(expected, query(grid, qx, qy, qx + w, qy + w), "step " + step);
        }
        int most = 0;
        for (List<Integer> list : lists) {
            most = Math.max(most, list.size());
        }
        assertTrue(most > 12, "the crowd fills cells: " + most);
    }

    /** The cells of a 4 x 4 grid of metre cells from (0, 0) that the box covers, row by row. */
    private static List<Integer> cellsOf(double[] box) {
        List<Integer> cells = new ArrayList<>();
        for (int r = clamp(box[1]); r <= clamp(box[3]); r++) {
            for (int c = clamp(box[0]); c <= clamp(box[2]); c++) {
                cells.add(r * 4 + c);
            }
        }
        return cells;
    }

    private static int clamp(double v) {
        return Math.max(0, Math.min(3, (int) Math.floor(v)));
    }

    private static double[] box(java.util.Random random, double x, double y) {
        double w = 0.1 + 0.5 * random.nextDouble();
        return new double[] {x, y, x + w, y + w};
    }

    /**
     * Along a segment, the cells visited are those whose centre is within the radius and half a cell's
     * diagonal of it, among the cells of its box grown by the radius, however long it is (a drive "for
     * ever" reaches far beyond the plan): the same as trying every cell of the box, which this does.
     */
    @Test
    void aSegmentFindsWhatTryingEveryCellOfItsBoxFinds() {
        double side = 50.0;
        Grid grid = new Grid(new RsRectangle(0, 0, side, side), 1.0, MAX_CELLS);
        java.util.Random random = new java.util.Random(5);
        List<double[]> boxes = new ArrayList<>();
        for (int id = 0; id < 400; id++) {
            double x = side * random.nextDouble();
            double y = side * random.nextDouble();
            double w = 0.05 + 0.6 * random.nextDouble();
            boxes.add(new double[] {x, y, x + w, y + w});
            grid.insert(id, x, y, x + w, y + w);
        }
        for (int i = 0; i < 2_000; i++) {
            double x0 = side * random.nextDouble();
            double y0 = side * random.nextDouble();
            double heading = 2 * Math.PI * random.nextDouble();
            double length = i % 4 == 0 ? 1e6 : i % 4 == 1 ? 3 * random.nextDouble() : side * random.nextDouble();
            double x1 = i % 10 == 0 ? x0 + length : x0 + length * Math.cos(heading);
            double y1 = i % 10 == 0 ? y0 : y0 + length * Math.sin(heading);
            double radius = i % 3 == 0 ? 0.0 : 0.7 * random.nextDouble();
            List<Integer> found = alongSegment(grid, x0, y0, x1, y1, radius);
            found.sort(null);
            assertEquals(everyCellOfTheBox(boxes, side, x0, y0, x1, y1, radius), found, "segment " + i);
        }
    }

    /**
     * The same away from the origin, for segments level, upright or all but either, of no length,
     * ending beyond a million kilometres or crossing the plan from far outside: however a row's columns
     * are bounded, no cell the exact test takes may be left out.
     */
    @Test
    void anySegmentAnywhereFindsWhatTryingEveryCellOfItsBoxFinds() {
        double side = 40.0;
        double left = -731.3;
        double bottom = 512.7;
        Grid grid = new Grid(new RsRectangle(left, bottom, side, side), 1.0, MAX_CELLS);
        java.util.Random random = new java.util.Random(6);
        List<double[]> boxes = new ArrayList<>();
        for (int id = 0; id < 300; id++) {
            double x = left + side * random.nextDouble();
            double y = bottom + side * random.nextDouble();
            double w = 0.05 + 0.6 * random.nextDouble();
            boxes.add(new double[] {x - left, y - bottom, x - left + w, y - bottom + w});
            grid.insert(id, x, y, x + w, y + w);
        }
        for (int i = 0; i < 20_000; i++) {
            double x0 = left + side * (1.4 * random.nextDouble() - 0.2);
            double y0 = bottom + side * (1.4 * random.nextDouble() - 0.2);
            double heading = 2 * Math.PI * random.nextDouble();
            double length = switch (i % 5) {
                case 0 -> 1e6;
                case 1 -> 3e9; // beyond where the margin for rounding is trusted
                case 2 -> 0.0;
                default -> side * random.nextDouble();
            };
            double dx = length * Math.cos(heading);
            double dy = length * Math.sin(heading);
            if (i % 7 == 0) {
                dy = dx * 1e-13; // all but level
            } else if (i % 7 == 1) {
                dx = dy * 1e-13; // all but upright
            } else if (i % 7 == 2) {
                dy = 0.0; // level
            } else if (i % 7 == 3) {
                dx = 0.0; // upright
            }
            double radius = i % 3 == 0 ? 0.0 : 0.7 * random.nextDouble();
            List<Integer> found = alongSegment(grid, x0, y0, x0 + dx, y0 + dy, radius);
            found.sort(null);
            assertEquals(everyCellOfTheBox(boxes, side, left, bottom, x0, y0, x0 + dx, y0 + dy, radius), found,
                    "segment " + i);
        }
    }

    /** The items in the cells (1 m, from 0 to side) that the box test admits, trying every cell of the box. */
    private static List<Integer> everyCellOfTheBox(List<double[]> boxes, double side, double x0, double y0, double x1,
                                                   double y1, double radius) {
        return everyCellOfTheBox(boxes, side, 0.0, 0.0, x0, y0, x1, y1, radius);
    }

    /**
     * The same for cells from (left, bottom), the boxes given from there and the segment where it is:
     * the grid's cell centres are worked out as it works them out.
     */
    private static List<Integer> everyCellOfTheBox(List<double[]> boxes, double side, double left, double bottom,
                                                   double x0, double y0, double x1, double y1, double radius) {
        int cells = (int) side;
        if (left != 0.0 || bottom != 0.0) {
            List<Integer> found = new ArrayList<>();
            double reach = radius + Math.sqrt(0.5);
            int c0 = clamp(Math.floor(Math.min(x0, x1) - radius - left), cells);
            int c1 = clamp(Math.floor(Math.max(x0, x1) + radius - left), cells);
            int r0 = clamp(Math.floor(Math.min(y0, y1) - radius - bottom), cells);
            int r1 = clamp(Math.floor(Math.max(y0, y1) + radius - bottom), cells);
            for (int id = 0; id < boxes.size(); id++) {
                double[] b = boxes.get(id);
                boolean hit = false;
                for (int r = Math.max(r0, clamp(Math.floor(b[1]), cells)); r <= Math.min(r1, clamp(Math.floor(b[3]), cells)); r++) {
                    for (int c = Math.max(c0, clamp(Math.floor(b[0]), cells)); c <= Math.min(c1, clamp(Math.floor(b[2]), cells)); c++) {
                        hit |= Outlines.squaredToSegment(left + (c + 0.5), bottom + (r + 0.5), x0, y0, x1, y1)
                                <= reach * reach;
                    }
                }
                if (hit) {
                    found.add(id);
                }
            }
            return found;
        }
        int c0 = clamp(Math.floor(Math.min(x0, x1) - radius), cells);
        int c1 = clamp(Math.floor(Math.max(x0, x1) + radius), cells);
        int r0 = clamp(Math.floor(Math.min(y0, y1) - radius), cells);
        int r1 = clamp(Math.floor(Math.max(y0, y1) + radius), cells);
        double reach = radius + Math.sqrt(0.5);
        List<Integer> found = new ArrayList<>();
        for (int id = 0; id < boxes.size(); id++) {
            double[] b = boxes.get(id);
            boolean hit = false;
            for (int r = Math.max(r0, clamp(Math.floor(b[1]), cells)); r <= Math.min(r1, clamp(Math.floor(b[3]), cells)); r++) {
                for (int c = Math.max(c0, clamp(Math.floor(b[0]), cells)); c <= Math.min(c1, clamp(Math.floor(b[2]), cells)); c++) {
                    hit |= Outlines.squaredToSegment(c + 0.5, r + 0.5, x0, y0, x1, y1) <= reach * reach;
                }
            }
            if (hit) {
                found.add(id);
            }
        }
        return found;
    }

    private static int clamp(double cell, int cells) {
        return (int) Math.max(0, Math.min(cells - 1, cell));
    }

    @Test
    void aLongThinAreaOfHugeExtentGetsLargerCellsInsteadOfAnArrayTooLargeForTheVm() {
        Grid grid = new Grid(new RsRectangle(0, 0, 1e300, 3), 1.0, MAX_CELLS);
        assertTrue(grid.cellCount() <= MAX_CELLS, grid.cellCount() + " cells");
        grid.insert(0, 1, 1, 2, 2);
        grid.insert(1, 1e300 - 1, 1, 1e300, 2);
        assertEquals(List.of(0), query(grid, 0, 0, 3, 3));
        assertEquals(List.of(1), query(grid, 1e300 - 1, 0, 1e300, 3));
        assertEquals(List.of(1), alongSegment(grid, 1e300 - 5, 1.5, 1e300 - 4, 1.5, 10));
    }

    @Test
    void theLargestPlanThatParsesIsIndexedWithinTheCellCap() {
        Grid grid = new Grid(new RsRectangle(-1e6, -1e6, 2e6, 2e6), 1.0, MAX_CELLS);
        assertTrue(grid.cellCount() <= MAX_CELLS, grid.cellCount() + " cells");
        grid.insert(0, -1e6, -1e6, -1e6 + 1, -1e6 + 1);
        grid.insert(1, 1e6 - 1, 1e6 - 1, 1e6, 1e6);
        assertEquals(List.of(1), alongSegment(grid, 1e6 - 3, 1e6 - 3, 1e6 - 2, 1e6 - 2, 1));
        assertEquals(List.of(0, 1), query(grid, -1e6, -1e6, 1e6, 1e6));
    }

    @Test
    void anItemFarOutsideASmallAreaIsStillFoundWhereItIs() {
        Grid grid = new Grid(new RsRectangle(0, 0, 3, 3), 1.0, MAX_CELLS);
        grid.insert(0, 1e12, -1e12, 1e12 + 1, -1e12 + 1);
        grid.insert(1, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.POSITIVE_INFINITY);
        assertEquals(List.of(0, 1), query(grid, 1e12, -1e12, 1e12, -1e12));
        grid.remove(0, 1e12, -1e12, 1e12 + 1, -1e12 + 1);
        grid.remove(1, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.POSITIVE_INFINITY);
        assertEquals(List.of(), query(grid, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY));
    }

    /** The indexes answer in item order (plan order, joining order) whatever the cells visited first. */
    @Test
    void aCollectionHoldsEachItemOnceInAscendingOrderHoweverManyCellsItSpans() {
        Grid grid = Grid.forIndex(new RsRectangle(0, 0, 10, 10));
        for (int id = 40; id >= 0; id--) {
            grid.insert(id, 9.5 - id * 0.2, 0.5, 9.6, 0.5 + id * 0.2);
        }
        int count = grid.collect(0, 0, 10, 10);
        List<Integer> found = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            found.add(grid.hit(i));
        }
        List<Integer> expected = new ArrayList<>();
        for (int id = 0; id <= 40; id++) {
            expected.add(id);
        }
        assertEquals(expected, found);
    }

    @Test
    void anAreaThatIsNotFiniteIsRefusedSayingSo() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Grid(new RsRectangle(0, 0, Double.POSITIVE_INFINITY, 1), 1.0, MAX_CELLS));
        assertTrue(e.getMessage().startsWith("a grid needs a finite area"), e.getMessage());
    }
}
