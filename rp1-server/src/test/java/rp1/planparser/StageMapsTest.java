package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsWall;

/**
 * Stage's real maps, at the sizes Stage's own worlds give them, become plans whose walls cover exactly
 * the black pixels, in far fewer walls than pixels. Skipped, with the reason, without Stage's archive
 * ({@link StageMaps}).
 */
class StageMapsTest {
    @TempDir
    Path dir;

    /**
     * @param metres the image's width in Stage's world files (cave: 16 m as in fasr.world, cave_filled as in
     *     benchmark/cave.world; hospital_section: 40 m, everything.world; hospital: 140 m,
     *     benchmark/hospital.world; autolab: 20 m, autolab.world; SFU: 180 m, circuit.world)
     * @param maxWalls what "far fewer walls than black pixels" means for this map
     */
    @ParameterizedTest(name = "{0} at {1} m")
    @CsvSource({"cave.png, 16, 2000", "cave_filled.png, 16, 2000", "hospital_section.png, 40, 4000",
            "hospital.png, 140, 20000", "autolab.png, 20, 4000", "SFU_1200x615.png, 180, 20000"})
    void aStageMapBecomesWallsCoveringExactlyItsBlackPixels(String image, double metres, int maxWalls) throws Exception {
        StageMaps.extract(dir, Set.of(image));
        MapSpec spec;
        OccupancyGrid grid;
        try (InputStream in = Files.newInputStream(dir.resolve(image))) {
            grid = MapImageReader.read(in, new MapSpec(image, 1, 0, 0, 0, 0.65, 0.196, false));
        }
        double resolution = metres / grid.width();
        Path yaml = dir.resolve("map.yaml");
        Files.writeString(yaml, "image: " + image + "\nresolution: " + resolution + "\norigin: [0, 0, 0]\n");
        long start = System.nanoTime();
        RsPlan plan = RsPlanParser.parseFile(yaml);
        long millis = (System.nanoTime() - start) / 1_000_000;
        int walls = plan.getWallArray().length;
        int black = grid.occupiedCount();
        System.out.printf("%s: %d x %d pixels of %.4f m, %d black, %d walls, read in %d ms%n", image, grid.width(),
                grid.height(), resolution, black, walls, millis);
        assertTrue(black > grid.width(), image + " has black pixels: " + black);
        assertTrue(walls <= maxWalls && walls * 5 < black, image + ": " + walls + " walls for " + black + " black pixels");
        assertEquals(black, coveredCells(plan, grid, resolution), "the walls cover the black pixels, each once");
    }

    /** Counts the cells the walls cover, failing on a cell covered twice or a white cell covered. */
    private static int coveredCells(RsPlan plan, OccupancyGrid grid, double resolution) {
        boolean[] seen = new boolean[grid.width() * grid.height()];
        int count = 0;
        for (RsWall w : plan.getWallArray()) {
            RsRectangle b = w.getBounds();
            int c0 = (int) Math.round(b.x / resolution);
            int c1 = (int) Math.round((b.x + b.width) / resolution);
            int rowsFromBottom0 = (int) Math.round(b.y / resolution);
            int rowsFromBottom1 = (int) Math.round((b.y + b.height) / resolution);
            assertEquals(4, w.getGeometry().length / 2, "a rectangle");
            for (int c = c0; c < c1; c++) {
                for (int up = rowsFromBottom0; up < rowsFromBottom1; up++) {
                    int row = grid.height() - 1 - up;
                    assertTrue(grid.isOccupied(c, row), w.getName() + " covers white pixel (" + c + ", " + row + ")");
                    assertTrue(!seen[row * grid.width() + c], "pixel (" + c + ", " + row + ") covered twice");
                    seen[row * grid.width() + c] = true;
                    count++;
                }
            }
        }
        return count;
    }
}
