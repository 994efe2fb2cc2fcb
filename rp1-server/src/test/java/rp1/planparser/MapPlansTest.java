package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsObject;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsPolygon;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTarget;
import rp1.rossum.RsWall;

/**
 * Plans from occupancy-grid maps: a map_server YAML file as the plan, and a {@code bitmap} declaration
 * in plan text; the occupied pixels, and only they, become walls, wherever the map is placed.
 */
class MapPlansTest {
    /** A small map with every kind of pixel: black walls, unknown grey ('?') and free white. */
    private static final String[] PICTURE = {
        "##########",
        "#........#",
        "#..##....#",
        "#..##..???",
        "#........#",
        "####..####"};

    @TempDir
    Path dir;

    private static RsPlan parseFile(Path file) throws Exception {
        return RsPlanParser.parseFile(file);
    }

    private static String failure(Path file) {
        return assertThrows(RsParsingException.class, () -> parseFile(file)).getMessage();
    }

    /** Whether (x, y) lies inside (or on) one of the plan's walls. */
    static boolean inWall(RsPlan plan, double x, double y) {
        for (RsWall w : plan.getWallArray()) {
            if (w.getPolygon().checkContainment(x, y) != RsPolygon.OUTSIDE) {
                return true;
            }
        }
        return false;
    }

    /** Fails unless the centre of each pixel of {@code picture} (resolution r, origin 0) is in a wall iff black. */
    private static void assertWallsArePicture(RsPlan plan, double r, String... picture) {
        for (int row = 0; row < picture.length; row++) {
            for (int c = 0; c < picture[row].length(); c++) {
                double x = (c + 0.5) * r;
                double y = (picture.length - row - 0.5) * r;
                assertEquals(picture[row].charAt(c) == '#', inWall(plan, x, y), "pixel (" + c + ", " + row + ")");
            }
        }
    }

    private static List<String> geometries(RsPlan plan) {
        return Arrays.stream(plan.getWallArray()).map(w -> Arrays.toString(w.getGeometry())).collect(Collectors.toList());
    }

    @Test
    void everyImageFormatGivesTheSameWallsExactlyWhereThePixelsAreBlack() throws Exception {
        RsPlan reference = parseFile(MapFiles.yaml(dir, "plain.pgm", MapFiles.plainPgm(PICTURE), "resolution: 0.1"));
        assertWallsArePicture(reference, 0.1, PICTURE);
        assertEquals(7, reference.getWallArray().length, "top, left side, the two parts of the right side, the two"
                + " parts of the bottom, and the block: " + geometries(reference));
        List<byte[]> images = List.of(MapFiles.rawPgm(255, PICTURE), MapFiles.rawPgm(65535, PICTURE),
                MapFiles.png(BufferedImage.TYPE_BYTE_GRAY, PICTURE), MapFiles.png(BufferedImage.TYPE_USHORT_GRAY, PICTURE),
                MapFiles.png(BufferedImage.TYPE_BYTE_BINARY, PICTURE), MapFiles.png(BufferedImage.TYPE_INT_ARGB, PICTURE));
        for (int i = 0; i < images.size(); i++) {
            RsPlan plan = parseFile(MapFiles.yaml(dir, "image" + i + ".img", images.get(i), "resolution: 0.1"));
            assertEquals(geometries(reference), geometries(plan), "image " + i);
        }
    }

    @Test
    void negateMakesWhiteTheWallsAndTheThresholdDecidesAboutGrey() throws Exception {
        String[] picture = {"#.?", "..#"};
        RsPlan negated = parseFile(MapFiles.yaml(dir, "n.pgm", MapFiles.rawPgm(255, picture), "resolution: 1",
                "negate: 1"));
        assertWallsArePicture(negated, 1.0, ".##", "##.");
        RsPlan lowThreshold = parseFile(MapFiles.yaml(dir, "t.pgm", MapFiles.rawPgm(255, picture), "resolution: 1",
                "occupied_thresh: 0.1", "free_thresh: 0.05"));
        assertWallsArePicture(lowThreshold, 1.0, "#.#", "..#");
    }

    @Test
    void aFullyTransparentPixelIsNoWall() throws Exception {
        BufferedImage image = new BufferedImage(2, 1, BufferedImage.TYPE_INT_ARGB);
        image.setRGB(0, 0, 0xFF000000);
        image.setRGB(1, 0, 0x00000000);
        java.io.ByteArrayOutputStream png = new java.io.ByteArrayOutputStream();
        javax.imageio.ImageIO.write(image, "png", png);
        RsPlan plan = parseFile(MapFiles.yaml(dir, "a.png", png.toByteArray(), "resolution: 1"));
        assertTrue(inWall(plan, 0.5, 0.5));
        assertTrue(!inWall(plan, 1.5, 0.5));
    }

    @Test
    void theOriginPlacesTheImagesLowerLeftCornerAndYawTurnsItAboutThatCorner() throws Exception {
        String[] pixel = {"#..", "..."};
        RsPlan moved = parseFile(MapFiles.yaml(dir, "m.pgm", MapFiles.rawPgm(255, pixel), "resolution: 0.5",
                "origin: [10, -2, 0]"));
        RsRectangle b = moved.getBounds();
        assertArrayEquals(new double[] {10.0, -1.5, 0.5, 0.5}, new double[] {b.x, b.y, b.width, b.height}, 1e-12);
        RsPlan turned = parseFile(MapFiles.yaml(dir, "t.pgm", MapFiles.rawPgm(255, pixel), "resolution: 0.5",
                "origin: [10, -2, " + Math.PI / 2 + "]"));
        b = turned.getBounds();
        assertArrayEquals(new double[] {9.0, -2.0, 0.5, 0.5}, new double[] {b.x, b.y, b.width, b.height}, 1e-12,
                "the top-left pixel, 0.5..1 m up the image, turned a quarter left about (10, -2)");
    }

    @Test
    void theShippedMapIsTwoRoomsADoorwayAndAPillarInAFewWalls() throws Exception {
        RsPlan plan = parseFile(TestPlans.shipped("rooms.yaml"));
        RsWall[] walls = plan.getWallArray();
        assertEquals(plan.getObjectCount(), walls.length, "a map file's plan holds only walls");
        assertTrue(walls.length <= 30, "merged into few walls: " + walls.length);
        assertEquals("map_1", walls[0].getName());
        assertEquals(MapWalls.DEFAULT_COLOR, walls[0].fillColor);
        assertTrue(inWall(plan, 0.05, 2.0) && inWall(plan, 4.95, 2.0) && inWall(plan, 2.5, 3.95), "outer walls");
        assertTrue(inWall(plan, 3.05, 1.0) && inWall(plan, 3.05, 3.0), "the dividing wall");
        assertTrue(!inWall(plan, 3.05, 2.0), "the doorway");
        assertTrue(inWall(plan, 1.5, 2.6) && inWall(plan, 1.5, 2.85) && !inWall(plan, 1.5, 2.95), "the pillar");
        assertTrue(!inWall(plan, 4.5, 3.7), "the unknown grey corner is not a wall");
        RsRectangle b = plan.getBounds();
        assertArrayEquals(new double[] {0, 0, 5, 4}, new double[] {b.x, b.y, b.width, b.height}, 1e-9);
    }

    @Test
    void aBitmapDeclarationPutsTheMapsWallsUnderTheRestOfThePlan() throws Exception {
        RsPlan plan = parseFile(TestPlans.shipped("rooms.txt"));
        RsPlan map = parseFile(TestPlans.shipped("rooms.yaml"));
        assertEquals(geometries(map), geometries(plan));
        assertEquals("rooms_1", plan.getWallArray()[0].getName());
        assertEquals("Two rooms from a map", plan.getCaption());
        assertTrue(plan.getObjectByName("home") instanceof RsPlacement);
        assertTrue(plan.getObjectByName("goal") instanceof RsTarget);
        assertEquals(2, plan.getNavLinkArray().length);
    }

    @Test
    void aBitmapTakesImageResolutionAndOriginInThePlansUnitsAndItsColours() throws Exception {
        Files.write(dir.resolve("p.pgm"), MapFiles.rawPgm(255, "#.", ".."));
        Path planFile = dir.resolve("plan.txt");
        Files.writeString(planFile, "units: feet;\nbitmap b { image: \"p.pgm\"; resolution: 1; origin: 2, 3, 90;"
                + " color: red; }\ntarget t { geometry: 0, 0, 1; }\n");
        RsPlan plan = parseFile(planFile);
        RsWall w = plan.getWallArray()[0];
        assertEquals("b_1", w.getName());
        assertEquals(Color.red, w.fillColor);
        assertEquals(Color.red, w.lineColor);
        RsRectangle box = w.getBounds();
        double foot = 1 / 3.2808;
        assertArrayEquals(new double[] {0, 3 * foot, foot, foot}, new double[] {box.x, box.y, box.width, box.height},
                1e-9, "the top-left pixel of a 2-pixel-high image (1 to 2 ft up) turned 90 degrees about (2, 3) ft");
    }

    @Test
    void aBitmapCanTakeItsMapFromAClassPathUrl() throws Exception {
        Path sub = Files.createDirectories(dir.resolve("maps"));
        MapFiles.yaml(sub, "u.pgm", MapFiles.rawPgm(255, "#"), "resolution: 1");
        String location = dir.resolve("plan.txt").toUri().toString();
        RsPlan plan = RsPlanParser.parse("bitmap { map: \"maps/u.yaml\"; }", location);
        assertEquals(1, plan.getWallArray().length);
        String absolute = sub.resolve("u.pgm").toString().replace("\\", "\\\\");
        RsPlan fromAbsolute = RsPlanParser.parse("bitmap { image: \"" + absolute + "\"; resolution: 1; }",
                "jar:file:/nowhere/rp1.jar!/FloorPlans/plan.txt");
        assertEquals(1, fromAbsolute.getWallArray().length, "an absolute path is a path, whatever names it");
    }

    @Test
    void badMapsAreReportedAtTheFileLineAndColumnThatNameThem() throws Exception {
        Path missing = dir.resolve("missing.yaml");
        Files.writeString(missing, "resolution: 0.1\nimage:   nowhere.pgm\n");
        assertEquals(missing + ":2:10: Cannot read the map image " + dir.resolve("nowhere.pgm") + ": no such file",
                failure(missing));

        Path truncated = MapFiles.yaml(dir, "cut.pgm", "P5 4 4 255\n\0\0\0".getBytes(StandardCharsets.ISO_8859_1),
                "resolution: 0.1");
        assertEquals(truncated + ":1:8: Cannot read the map image " + dir.resolve("cut.pgm")
                + ": the image data ends before the last pixel (truncated file?)", failure(truncated));

        Path huge = MapFiles.yaml(dir, "huge.pgm", "P5 100000 100000 255\n".getBytes(StandardCharsets.US_ASCII),
                "resolution: 0.1");
        assertTrue(failure(huge).endsWith(": image of 100000 × 100000 pixels: a map must have at least one and at most "
                + OccupancyGrid.MAX_CELLS + " pixels"), failure(huge));

        Path notImage = MapFiles.yaml(dir, "text.png", "hello".getBytes(StandardCharsets.US_ASCII), "resolution: 1");
        assertTrue(failure(notImage).contains(":1:8: Cannot read the map image " + dir.resolve("text.png")
                + ": not an image this server can read"), failure(notImage));

        Path badSample = MapFiles.yaml(dir, "bad.pgm", "P2 2 1 15\n3 16\n".getBytes(StandardCharsets.US_ASCII),
                "resolution: 1");
        assertTrue(failure(badSample).endsWith("pixel (1, 0) has value 16, above the maximum gray value 15"));

        Path white = MapFiles.yaml(dir, "white.pgm", MapFiles.rawPgm(255, "...", "..."), "resolution: 1");
        assertEquals(white + ":1:8: Empty floor plan: no pixel of " + dir.resolve("white.pgm")
                + " is occupied (darker than occupied_thresh 0.65)", failure(white));

        Path far = MapFiles.yaml(dir, "far.pgm", MapFiles.rawPgm(255, "#."), "resolution: 1", "origin: [999999, 0, 0]");
        assertTrue(failure(far).startsWith(far + ":3:9: Map out of range: the image (2 × 1 pixels of 1.0 m) has a"
                + " corner at (1000001.0, 0.0) m, beyond the limit of 1000000 m"), failure(far));
    }

    @Test
    void badBitmapDeclarationsAreReportedWhereTheyAreWritten() throws Exception {
        Files.write(dir.resolve("p.pgm"), MapFiles.rawPgm(255, "#."));
        assertEquals("4:1: Missing resolution specification: a bitmap needs image: \"FILE\"; and resolution: LENGTH;"
                + " (or map: \"FILE.yaml\";)", planFailure("bitmap {\n image: \"p.pgm\";\n origin: 0, 0;\n}"));
        assertEquals("1:10: Cannot read the map image " + dir.resolve("q.pgm") + ": no such file",
                planFailure("bitmap { image: \"q.pgm\"; resolution: 1; }"));
        assertEquals("1:10: A bitmap takes either map (a map file) or image and resolution, not both",
                planFailure("bitmap { map: \"p.yaml\"; image: \"p.pgm\"; }"));
        assertEquals("2:43: Duplicate object name b_1: bitmap names its walls NAME_1, NAME_2, ... and an earlier"
                + " object has this name", planFailure("wall b_1 { geometry: 0, 0, 1, 0, 1; }\n"
                + "bitmap b { image: \"p.pgm\"; resolution: 1; }"));
        assertEquals("1:38: Resolution must be above zero, found 0",
                planFailure("bitmap { image: \"p.pgm\"; resolution: 0; }"));
        assertEquals("1:35: Invalid number of parameters in origin specification: expected 2 or 3 (x, y of the"
                + " image's lower-left corner, and its rotation in degrees), found 1",
                planFailure("bitmap { image: \"p.pgm\"; origin: 1; }"));
        assertEquals("1:62: Object out of range: bitmap b: the image (2 × 1 pixels of 1.0 m) has a corner at"
                + " (1000001.0, 0.0) m, beyond the limit of 1000000 m (1000 km) from the origin for any coordinate or"
                + " length of a plan", planFailure("bitmap b { image: \"p.pgm\"; resolution: 1; origin: 999999, 0; }"));
        assertEquals("1:49: negate must be 0 or 1, found 2",
                planFailure("bitmap { image: \"p.pgm\"; resolution: 1; negate: 2; }"));
    }

    @Test
    void aBadMapFileNamedByABitmapIsReportedInThatFile() throws Exception {
        Files.writeString(dir.resolve("bad.yaml"), "image: p.pgm\nresolution: -1\n");
        assertEquals(dir.resolve("bad.yaml") + ":2:13: resolution must be above zero (metres per pixel), found -1",
                assertThrows(RsParsingException.class, () -> RsPlanParser.parse("bitmap { map: \"bad.yaml\"; }",
                        dir.resolve("plan.txt").toString())).getMessage());
    }

    private String planFailure(String text) {
        String file = dir.resolve("plan.txt").toString();
        RsParsingException e = assertThrows(RsParsingException.class, () -> RsPlanParser.parse(text, file));
        return e.getLine() + ":" + e.getColumn() + ": " + e.getReason();
    }

    @Test
    void objectsKeepDeclarationOrderAroundABitmap() throws Exception {
        Files.write(dir.resolve("p.pgm"), MapFiles.rawPgm(255, "#.#"));
        RsPlan plan = RsPlanParser.parse("target t { geometry: 0, 0, 1; }\nbitmap m { image: \"p.pgm\"; resolution: 1; }\n"
                + "target u { geometry: 0, 0, 1; }", dir.resolve("plan.txt").toString());
        assertEquals(List.of("t", "m_1", "m_2", "u"), plan.getObjects().stream().map(RsObject::getName)
                .collect(Collectors.toList()));
    }
}
