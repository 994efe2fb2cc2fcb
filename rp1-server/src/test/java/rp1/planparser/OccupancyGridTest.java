package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The rectangles cover exactly the occupied cells, once each, and are as few as the shape allows. */
class OccupancyGridTest {
    /** A grid from rows of text: '#' occupied, anything else free; the first string is the top row. */
    static OccupancyGrid grid(String... rows) {
        OccupancyGrid g = new OccupancyGrid(rows[0].length(), rows.length);
        for (int r = 0; r < rows.length; r++) {
            for (int c = 0; c < rows[r].length(); c++) {
                if (rows[r].charAt(c) == '#') {
                    g.occupy(c, r);
                }
            }
        }
        return g;
    }

    /** Fails unless the rectangles cover every occupied cell exactly once and no free cell. */
    static void assertExactCover(OccupancyGrid g, List<OccupancyGrid.Cells> cover) {
        int[] times = new int[g.width() * g.height()];
        for (OccupancyGrid.Cells c : cover) {
            assertTrue(c.width() > 0 && c.height() > 0, "empty rectangle " + c);
            for (int r = c.row(); r < c.row() + c.height(); r++) {
                for (int col = c.column(); col < c.column() + c.width(); col++) {
                    times[r * g.width() + col]++;
                }
            }
        }
        for (int r = 0; r < g.height(); r++) {
            for (int c = 0; c < g.width(); c++) {
                assertEquals(g.isOccupied(c, r) ? 1 : 0, times[r * g.width() + c], "cell (" + c + ", " + r + ")");
            }
        }
    }

    @Test
    void aSolidBlockIsOneRectangle() {
        OccupancyGrid g = grid(
                "......",
                ".####.",
                ".####.",
                ".####.",
                "......");
        assertEquals(List.of(new OccupancyGrid.Cells(1, 1, 4, 3)), g.rectangles());
    }

    @Test
    void anLShapeIsTwoRectanglesAndARoomOutlineFour() {
        OccupancyGrid l = grid(
                "#...",
                "#...",
                "####");
        assertEquals(2, l.rectangles().size());
        assertExactCover(l, l.rectangles());
        OccupancyGrid room = grid(
                "########",
                "#......#",
                "#......#",
                "########");
        assertEquals(4, room.rectangles().size());
        assertExactCover(room, room.rectangles());
    }

    @Test
    void tallThinBarsAreMergedAlongColumnsNotRowByRow() {
        OccupancyGrid bars = grid(
                "#.#.#",
                "#.#.#",
                "#.#.#",
                "#.#.#",
                "#.#.#",
                "##..#");
        List<OccupancyGrid.Cells> cover = bars.rectangles();
        assertExactCover(bars, cover);
        assertEquals(4, cover.size(), "three bars and the foot: " + cover);
    }

    @Test
    void randomGridsAreCoveredExactly() {
        Random random = new Random(25);
        for (int trial = 0; trial < 200; trial++) {
            int w = 1 + random.nextInt(40);
            int h = 1 + random.nextInt(40);
            double density = random.nextDouble();
            OccupancyGrid g = new OccupancyGrid(w, h);
            for (int r = 0; r < h; r++) {
                for (int c = 0; c < w; c++) {
                    if (random.nextDouble() < density) {
                        g.occupy(c, r);
                    }
                }
            }
            List<OccupancyGrid.Cells> cover = g.rectangles();
            assertExactCover(g, cover);
            assertTrue(cover.size() <= g.occupiedCount());
        }
    }

    @Test
    void anEmptyGridHasNoRectangles() {
        assertEquals(List.of(), grid("....", "....").rectangles());
    }
}
