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
