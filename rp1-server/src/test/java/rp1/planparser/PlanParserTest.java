package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsFeet;
import rp1.rossum.RsInches;
import rp1.rossum.RsKilometers;
import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;
import rp1.rossum.RsWall;

/** The language's rules and the original's accepted quirks, one small plan each. */
class PlanParserTest {
    private static final double EPS = 1e-12;
    private static final String WALL = "wall w { geometry: 0, 0, 1, 0, 0.1; }\n";

    private static RsPlan parse(String text) throws RsParsingException {
        return RsPlanParser.parse(text, "p.txt");
    }

    private static RsParsingException failure(String text) {
        return assertThrows(RsParsingException.class, () -> parse(text));
    }

    @Test
    void errorMessageStartsWithFileLineAndColumn() {
        RsParsingException e = failure(WALL + "  ;");
        assertEquals("p.txt", e.getFileName());
        assertEquals(2, e.getLine());
        assertEquals(3, e.getColumn());
        assertEquals("p.txt:2:3: " + e.getReason(), e.getMessage());
        assertTrue(e.getReason().startsWith("Invalid syntax where identifier expected"));
        assertTrue(e.getReason().endsWith("found ';'"), e.getReason());
    }

    @Test
    void planRecordsFileNameCaptionAndUnits() throws Exception {
        RsPlan plan = parse("caption: \"First\"; caption: \"Sec\\tond\"; units: feet;" + WALL);
        assertEquals("p.txt", plan.getFileName());
        assertEquals("Sec\tond", plan.getCaption());
        assertInstanceOf(RsFeet.class, plan.getUnits());
    }

    @Test
    void defaultsAreMetresAndNoCaption() throws Exception {
        RsPlan plan = parse(WALL);
        assertEquals("meters", plan.getUnits().getName());
        assertNull(plan.getCaption());
    }

    @Test
    void lengthsAreConvertedWithRp1sFactorsAndUnitsAffectOnlyWhatFollows() throws Exception {
        RsPlan plan = parse("target m { geometry: 1, 2, 3; }\n"
                + "units: feet;   target f { geometry: 3.2808, 1, 1; }\n"
                + "units: inches; target i { geometry: 39.3696, 1, 1; }\n"
                + "units: kilometers; target k { geometry: 0.001, 1, 1; }\n");
        assertEquals(1.0, ((RsTarget) plan.getObjectByName("m")).x, EPS);
        assertEquals(1.0, ((RsTarget) plan.getObjectByName("f")).x, EPS);
        assertEquals(1 / 3.2808, ((RsTarget) plan.getObjectByName("f")).radius, EPS);
        assertEquals(1.0, ((RsTarget) plan.getObjectByName("i")).x, EPS);
        assertEquals(1 / 39.3696, ((RsTarget) plan.getObjectByName("i")).y, EPS);
        assertEquals(1.0, ((RsTarget) plan.getObjectByName("k")).x, EPS);
        assertEquals(1000.0, ((RsTarget) plan.getObjectByName("k")).radius, EPS);
        assertInstanceOf(RsKilometers.class, plan.getUnits());
    }

    @Test
    void unitsTakesTheTokenAfterItUnchecked() throws Exception {
        assertInstanceOf(RsInches.class, parse("units = inches;" + WALL).getUnits());
        assertInstanceOf(RsInches.class, parse("units inches inches;" + WALL).getUnits());
        RsParsingException e = failure("units inches;" + WALL);
        assertTrue(e.getReason().startsWith("Invalid syntax where units specification expected"), e.getReason());
    }

    @Test
    void unitNamesAreLowerCaseOnly() {
        assertTrue(failure("units: Meters;" + WALL).getReason()
                .startsWith("Invalid or unimplemented units specification Meters"));
    }

    @Test
    void targetPlacementNodeAndLinkSkipStrayTokens() throws Exception {
        RsPlan plan = parse("target t { ; geometry: 1,1,1; 5 }\n"
                + "placement p { { geometry: 1, 1, 90, 1; \"x\" }\n"
                + "node a { 1.5 geometry: 0, 0; } node b { geometry: 1, 0; }\n"
                + "link l { ; nodes: a, b; ; }\n");
        assertEquals(5, plan.getObjectCount());
    }

    @Test
    void wallObstacleAndPaintRejectStrayTokens() {
        for (String decl : new String[] {"wall w { ; geometry: 0,0,1,0,1; }",
            "obstacle o { ; polygon: 3, 1; }", "paint p { 5 polygon: 3, 1; }"}) {
            assertTrue(failure(decl).getReason().startsWith("Invalid syntax where object specification expected"),
                    decl);
        }
    }

    @Test
    void repeatedSpecificationsLastOneWins() throws Exception {
        RsPlan plan = parse("target t { color: red; geometry: 1, 1, 1; color: blue; geometry: 2, 3, 4;"
                + " lineColor: green; label: \"a\"; label: \"b\"; lineWidth: 1; lineWidth: 4; }");
        RsTarget t = (RsTarget) plan.getObjectByName("t");
        assertArrayEquals(new double[] {2, 3, 4}, t.getGeometry());
        assertEquals(Color.blue, t.fillColor);
        assertEquals(Color.green, t.lineColor);
        assertEquals("b", t.label);
        assertEquals(4, t.lineWidth);
    }

    @Test
    void defaultColoursPerType() throws Exception {
        RsPlan plan = parse(WALL + "obstacle o { polygon: 3, 1; } paint p { polygon: 4, 1; }\n"
                + "target t { geometry: 0, 0, 1; } placement h { geometry: 0, 0, 0, 1; }\n"
                + "node a { geometry: 0, 0; } node b { geometry: 1, 1; } link l { nodes: a, b; }");
        assertColours(plan, "w", Color.lightGray, Color.darkGray);
        assertColours(plan, "o", Color.lightGray, Color.darkGray);
        assertColours(plan, "p", Color.lightGray, Color.lightGray);
        assertColours(plan, "t", Color.lightGray, Color.lightGray);
        assertColours(plan, "h", Color.darkGray, Color.darkGray);
        assertColours(plan, "a", Color.cyan, Color.cyan);
        assertColours(plan, "l", Color.cyan, Color.cyan);
    }

    private static void assertColours(RsPlan plan, String name, Color fill, Color line) {
        assertEquals(fill, plan.getObjectByName(name).fillColor, name + " fill");
        assertEquals(line, plan.getObjectByName(name).lineColor, name + " line");
    }

    @Test
    void theThirteenColourNamesAreAccepted() throws Exception {
        String[] names = {"black", "blue", "cyan", "darkGray", "gray", "green", "lightGray", "magenta", "orange",
            "pink", "red", "white", "yellow"};
        StringBuilder text = new StringBuilder();
        for (String n : names) {
            text.append("node ").append(n).append(" { geometry: 0, 0; color: ").append(n).append("; }\n");
        }
        RsPlan plan = parse(text.toString());
        assertEquals(new Color(255, 200, 0), plan.getObjectByName("orange").lineColor);
        assertEquals(new Color(255, 175, 175), plan.getObjectByName("pink").fillColor);
        assertTrue(failure("node n { geometry: 0, 0; color: Red; }").getReason()
                .startsWith("Invalid value where color name expected: \"Red\""));
    }

    @Test
    void unnamedAndNumberedObjectsGetTheOriginalsSynthesizedNames() throws Exception {
        RsPlan plan = parse("target { geometry: 0,0,1; }\n"
                + "target 16 { geometry: 0,0,1; }\n"
                + "target { geometry: 0,0,1; }\n"
                + "target 3 { geometry: 0,0,1; }\n");
        String[] names = plan.getObjects().stream().map(o -> o.getName()).toArray(String[]::new);
        assertArrayEquals(new String[] {"0x00000001", "0x0000001g", "0x0000001h", "0x00000003"}, names);
    }

    @Test
    void numberedNameCollidingWithAnEarlierOneIsADuplicate() {
        RsParsingException e = failure("target { geometry: 0,0,1; }\ntarget 1 { geometry: 0,0,1; }");
        assertTrue(e.getReason().startsWith("Duplicate object name 0x00000001"), e.getReason());
        assertEquals(2, e.getLine());
        assertEquals(8, e.getColumn());
    }

    @Test
    void namesShareOneNamespaceAcrossTypes() {
        assertTrue(failure(WALL + "node w { geometry: 0, 0; }").getReason().startsWith("Duplicate object name w"));
    }

    @Test
    void wallBecomesTheRectangleAroundItsCentreLine() throws Exception {
        RsWall w = (RsWall) parse("wall w { geometry: 1, 1, 1, 3, 0.5; constraint: fixed; }").getObjectByName("w");
        assertArrayEquals(new double[] {1.25, 1, 1.25, 3, 0.75, 3, 0.75, 1}, w.getGeometry(), EPS);
    }

    @Test
    void zeroLengthWallGeometryIsIgnored() throws Exception {
        RsPlan plan = parse("wall w { geometry: 0, 0, 2, 0, 0.5; geometry: 1, 1, 1, 1, 0.5; }");
        assertEquals(2.0, ((RsWall) plan.getObjectByName("w")).getGeometry()[2], EPS);
        assertTrue(failure("wall w { geometry: 1, 1, 1, 1, 0.5; }").getReason()
                .startsWith("Missing or invalid geometry specification"));
    }

    @Test
    void regularPolygonStartsOnPlusXAnticlockwiseThenRotatesThenMoves() throws Exception {
        RsWall o = (RsWall) parse("obstacle o { polygon: 4, 2; orientation: 90; offset: 10, 20; }")
                .getObjectByName("o");
        assertArrayEquals(new double[] {10, 22, 8, 20, 10, 18, 12, 20}, o.getGeometry(), 1e-12);
    }

    @Test
    void orientationIsDegreesWhateverTheUnits() throws Exception {
        RsWall o = (RsWall) parse("units: inches; obstacle o { geometry: 0,0, 39.3696,0, 0,39.3696;"
                + " orientation: 180; }").getObjectByName("o");
        assertArrayEquals(new double[] {0, 0, -1, 0, 0, -1}, o.getGeometry(), 1e-12);
    }

    @Test
    void repeatedClosingVertexIsDropped() throws Exception {
        RsPaint p = (RsPaint) parse("paint p { geometry: 0,0, 1,0, 1,1, 0,0; region: 4; }").getObjectByName("p");
        assertEquals(3, p.getSegmentArray().length);
        assertEquals(4, p.getRegion());
    }

    @Test
    void minusMayBeSeparatedFromItsNumberButPlusIsNotASign() throws Exception {
        RsTarget t = (RsTarget) parse("target t { geometry: - 1, -\n2, .; }").getObjectByName("t");
        assertArrayEquals(new double[] {-1, -2, 0}, t.getGeometry());
        assertTrue(failure("target t { geometry: +1, 2, 3; }").getReason()
                .startsWith("Invalid syntax where numeric specification expected"));
    }

    @Test
    void hexadecimalIntegersAreNumbers() throws Exception {
        RsTarget t = (RsTarget) parse("target t { geometry: 0x10, 0, 1; lineWidth: 0x3; }").getObjectByName("t");
        assertEquals(16.0, t.x);
        assertEquals(3, t.lineWidth);
    }

    @Test
    void placementOrientationBecomesRadiansUnnormalized() throws Exception {
        RsPlacement p = (RsPlacement) parse("units: feet; placement p { geometry: 3.2808, 0, 720, 3.2808; }")
                .getObjectByName("p");
        assertArrayEquals(new double[] {1, 0, 4 * Math.PI, 1}, p.getGeometry(), EPS);
    }

    @Test
    void linksJoinEarlierNodesAndAreRecordedAtBothEnds() throws Exception {
        RsPlan plan = parse("node a { geometry: 0, 0; label: \"A\"; } node b { geometry: 3, 4; }\n"
                + "link l { nodes: a, b; label: \"road\"; color: red; } link m { nodes: b, a; }");
        RsNavLink l = (RsNavLink) plan.getObjectByName("l");
        RsNavNode a = (RsNavNode) plan.getObjectByName("a");
        RsNavNode b = (RsNavNode) plan.getObjectByName("b");
        assertSame(a, l.n0);
        assertSame(b, l.n1);
        assertEquals(5.0, l.getLength(), EPS);
        assertEquals("road", l.getLabel());
        assertEquals(2, a.link.length);
        assertSame(l, b.link[0]);
        assertSame(plan.getObjectByName("m"), b.link[1]);
    }

    @Test
    void linkMayNotNameALaterNode() {
        RsParsingException e = failure("node a { geometry: 0, 0; } link l { nodes: a, b; } node b { geometry: 1, 1; }");
        assertTrue(e.getReason().startsWith("Specified node was not defined \"b\""), e.getReason());
    }

    @Test
    void objectsKeepDeclarationOrderAndDefineTheExtent() throws Exception {
        RsPlan plan = parse("paint p { polygon: 4, 1; } " + WALL + "node n { geometry: 5, 5; }"
                + " target t { geometry: -2, 0, 0.5; }");
        assertEquals("p", plan.getObjects().get(0).getName());
        assertEquals("n", plan.getObjects().get(2).getName());
        assertEquals(-2.5, plan.getBounds().x, EPS);
        assertEquals(-1.0, plan.getBounds().y, EPS);
        assertEquals(7.505, plan.getBounds().width, EPS);
        assertEquals(6.005, plan.getBounds().height, EPS);
    }

    @Test
    void lineEndingsDoNotChangeThePlanOrTheErrorPositions() throws Exception {
        String text = "units: meters;\n// comment\ncaption: \"c\";\n" + WALL + "node n {\ngeometry: 1,\n2;\n}\n";
        for (String nl : new String[] {"\r\n", "\r"}) {
            RsPlan plan = parse(text.replace("\n", nl));
            assertEquals(2, plan.getObjectCount());
            assertEquals(2.0, ((RsNavNode) plan.getObjectByName("n")).y);
            RsParsingException e = failure((text + "node m { geometry: 1 }").replace("\n", nl));
            assertEquals(9, e.getLine());
            assertEquals(22, e.getColumn());
        }
    }

    @Test
    void fileIsDecodedAsUtf8(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("u.txt");
        Files.write(file, ("\uFEFFcaption: \"Caf\u00e9 \u2013 \u00fcber\";" + WALL).getBytes(StandardCharsets.UTF_8));
        RsPlan plan = RsPlanParser.parseFile(file);
        assertEquals("Caf\u00e9 \u2013 \u00fcber", plan.getCaption());
        assertEquals(file.toString(), plan.getFileName());
    }

    @Test
    void parseFileErrorsNameTheFile(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("bad.txt");
        Files.writeString(file, "wall w { geometry: 0, 0, 1, 0; }");
        RsParsingException e = assertThrows(RsParsingException.class, () -> RsPlanParser.parseFile(file));
        assertTrue(e.getMessage().startsWith(file + ":1:30: Invalid number of parameters in geometry"),
                e.getMessage());
    }

    @Test
    void tooManyNumbersInOneListAreRefused() {
        StringBuilder text = new StringBuilder("obstacle o { geometry: 0");
        for (int i = 0; i < ParserLimits.MAX_LIST_NUMBERS; i++) {
            text.append(",1");
        }
        RsParsingException e = failure(text.append("; }").toString());
        assertTrue(e.getReason().startsWith("Too many numbers in one specification"), e.getReason());
    }

    @Test
    void manyVertexPolygonIsCheckedQuickly() throws Exception {
        int n = 20_000;
        StringBuilder text = new StringBuilder("paint circle { geometry: ");
        for (int k = 0; k < n; k++) {
            double a = 2 * Math.PI * k / n;
            text.append(k == 0 ? "" : ", ").append(Math.cos(a)).append(", ").append(Math.sin(a));
        }
        RsPaint p = (RsPaint) parse(text.append("; }").toString()).getObjectByName("circle");
        assertEquals(n, p.getSegmentArray().length);
    }
}
