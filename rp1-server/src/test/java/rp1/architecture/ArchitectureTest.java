package rp1.architecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The package rules of docs/architecture.md, checked on the sources: the simulation core runs
 * headless, the world knows nothing of client sessions, the world's parts do not call back into its
 * façade, and the view reaches the model only through the simulation's inputs and snapshots.
 */
class ArchitectureTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", "."));
    private static final Path SOURCES = ROOT.resolve("rp1-server/src/main/java");

    /**
     * What the view may use of the server: the simulation (its inputs: mouse clicks, "Remove Paint
     * Trails"; its time; observers), snapshots, and the settings. Not the world, the scheduler, the
     * sessions or the transports. Pictures draw the paths the robots took from the run statistics'
     * trails: an observer that changes nothing, as a snapshot is.
     */
    private static final List<String> VIEW_MAY_USE = List.of(
            "rp1.simulator.Simulation", "rp1.simulator.snapshot", "rp1.simulator.config",
            "rp1.simulator.outcome.RunStatistics", "rp1.simulator.outcome.Trail");
    /**
     * The accessors of {@code Simulation} that hand out the model itself. The view reads the floor
     * plan (fixed for the run) through {@code getWorld().getPlan()} and nothing else of them.
     */
    private static final Pattern MODEL_ACCESS = Pattern.compile(
            "\\.(?:getScheduler|getInputs|getSessions)\\(|\\.getWorld\\(\\)(?!\\.getPlan\\(\\))");

    /**
     * The one class of the plan parser that decodes map images (PNG through {@code javax.imageio}, whose
     * pictures are {@code java.awt.image} rasters; both work headless). The rest of the parser, like the
     * core, uses {@code java.awt.Color} only.
     */
    private static final String IMAGE_DECODER = "rp1-server/src/main/java/rp1/planparser/MapImageReader.java";

    @Test
    void theCoreUsesNoAwtOrSwingButColor() throws IOException {
        List<String> found = violations("rp1/simulator", ArchitectureTest::awtBeyondColor);
        assertEquals("", String.join("\n", found), "rp1.simulator.* must run headless (java.awt.Color only)");
    }

    @Test
    void thePlanParserDecodesImagesInOneClassAndUsesNoOtherAwtButColor() throws IOException {
        List<String> found = violations("rp1/planparser", r -> awtBeyondColor(r) && !(r.where().startsWith(IMAGE_DECODER + ":")
                && (r.isIn("java.awt.image") || r.isIn("javax.imageio"))));
        assertEquals("", String.join("\n", found), "rp1.planparser uses java.awt.Color, and java.awt.image and"
                + " javax.imageio only in " + IMAGE_DECODER);
        assertTrue(awtBeyondColor(new References.Reference("javax.imageio.ImageIO", "X.java:1")));
        assertTrue(awtBeyondColor(new References.Reference("java.awt.image.BufferedImage", "X.java:1")));
    }

    /** AWT, Swing or image decoding, other than {@code java.awt.Color}. */
    private static boolean awtBeyondColor(References.Reference r) {
        return (r.isIn("java.awt") || r.isIn("javax.swing") || r.isIn("javax.imageio")) && !r.name().equals("java.awt.Color");
    }

    @Test
    void theWorldDoesNotKnowSessions() throws IOException {
        List<String> found = violations("rp1/simulator/world", r -> r.isIn("rp1.simulator.session"));
        assertEquals("", String.join("\n", found), "rp1.simulator.world must not use rp1.simulator.session");
    }

    /**
     * {@code World} is the façade over the world's parts (placements, motion, contacts, the broad
     * phase): they answer it and never call back into it, so each can be read and changed alone.
     * Only its listener interface names it.
     */
    @Test
    void theWorldsPartsDoNotUseTheWorld() throws IOException {
        Pattern world = Pattern.compile("\\bWorld\\b");
        List<String> found = new ArrayList<>();
        for (Path file : javaFiles("rp1/simulator/world")) {
            String simple = file.getFileName().toString();
            if (simple.equals("World.java") || simple.equals("WorldListener.java")) {
                continue;
            }
            String name = name(file);
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            List<String> code = References.codeOnly(lines);
            for (int i = 0; i < code.size(); i++) {
                if (world.matcher(code.get(i)).find()) {
                    found.add(name + ":" + (i + 1) + ": " + lines.get(i).trim());
                }
            }
        }
        assertEquals("", String.join("\n", found), "the world's parts must not use World");
    }

    @Test
    void theViewUsesOnlyTheSimulationSnapshotsAndSettingsOfTheServer() throws IOException {
        List<String> found = violations("rp1/view", ArchitectureTest::forbiddenToTheView);
        assertEquals("", String.join("\n", found), "rp1.view may use of rp1.simulator only " + VIEW_MAY_USE);
    }

    @Test
    void theViewTakesNothingButThePlanFromTheSimulationsAccessors() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path file : javaFiles("rp1/view")) {
            found.addAll(modelAccess(name(file), Files.readAllLines(file, StandardCharsets.UTF_8)));
        }
        assertEquals("", String.join("\n", found), "the view reads the model through snapshots only");
    }

    @Test
    void theServersPackagesUseEachOtherInOneDirectionOnly() throws IOException {
        // A ring of packages (batch used launch, whose view hook used the view, which used batch's
        // trails) is one piece that reads as several.
        PackageGraph graph = new PackageGraph();
        for (Path file : javaFiles("rp1")) {
            String from = PackageGraph.packageOf(ROOT.relativize(file).toString()
                    .replaceFirst("^rp1-server/src/main/java/", "").replace('/', '.'));
            for (References.Reference r : References.in(name(file), Files.readAllLines(file, StandardCharsets.UTF_8))) {
                if (r.isIn("rp1") && !r.isIn("rp1.rossum")) {
                    graph.add(from, PackageGraph.packageOf(r.name()));
                }
            }
        }
        assertEquals(List.of(), graph.rings(), "packages of the server that use one another");
    }

    @Test
    void aRingOfPackagesIsFoundAndPackagesAreReadOffQualifiedNames() {
        PackageGraph graph = new PackageGraph();
        graph.add("a", "b");
        graph.add("b", "c");
        graph.add("c", "a");
        graph.add("c", "d");
        graph.add("d", "d");
        assertEquals(List.of(Set.of("a", "b", "c")), graph.rings());
        assertEquals("rp1.simulator.world", PackageGraph.packageOf("rp1.simulator.world.Robot"));
        assertEquals("rp1.simulator", PackageGraph.packageOf("rp1.simulator.Simulation.EventListener"));
        assertEquals("rp1.view", PackageGraph.packageOf("rp1.view.*"));
    }

    @Test
    void referencesInCodeAreFoundAndCommentsAndStringsIgnored() {
        List<String> lines = List.of(
                "package rp1.simulator.world;",
                "import java.awt.Color;",
                "import javax.swing.*;",
                "/** Not {@link java.awt.Point}, nor",
                " * rp1.simulator.session.ClientSession. */",
                "class X { String s = \"-Djava.awt.headless=true\"; // java.awt.Frame",
                "    java.awt.geom.Point2D p; rp1.simulator.session.Request r; char q = '\"'; }");
        List<String> names = References.in("X.java", lines).stream().map(References.Reference::toString)
                .collect(Collectors.toList());
        assertEquals(List.of("X.java:2: java.awt.Color", "X.java:3: javax.swing.*", "X.java:7: java.awt.geom.Point2D",
                "X.java:7: rp1.simulator.session.Request"), names);
    }

    @Test
    void theViewsUseOfTheModelIsFoundWithItsFileAndLine() {
        List<String> lines = List.of(
                "RsPlan plan = simulation.getWorld().getPlan();",
                "World w = simulation.getWorld();",
                "// simulation.getScheduler() in a comment",
                "double t = simulation.getScheduler().now();");
        assertEquals(List.of("V.java:2: World w = simulation.getWorld();",
                "V.java:4: double t = simulation.getScheduler().now();"), modelAccess("V.java", lines));
        assertTrue(forbiddenToTheView(new References.Reference("rp1.simulator.world.World", "V.java:1")));
        assertTrue(forbiddenToTheView(new References.Reference("rp1.simulator.SimulationSettings", "V.java:1")));
        assertTrue(!forbiddenToTheView(new References.Reference("rp1.simulator.Simulation", "V.java:1")));
        assertTrue(!forbiddenToTheView(new References.Reference("rp1.simulator.snapshot.WorldSnapshot", "V.java:1")));
    }

    private static boolean forbiddenToTheView(References.Reference r) {
        return r.isIn("rp1.simulator") && VIEW_MAY_USE.stream().noneMatch(r::isIn);
    }

    private static List<String> modelAccess(String file, List<String> lines) {
        List<String> found = new ArrayList<>();
        List<String> code = References.codeOnly(lines);
        for (int i = 0; i < code.size(); i++) {
            Matcher m = MODEL_ACCESS.matcher(code.get(i));
            if (m.find()) {
                found.add(file + ":" + (i + 1) + ": " + lines.get(i).trim());
            }
        }
        return found;
    }

    /** The references of the sources under {@code dir} (a package path) that {@code forbidden} matches. */
    private static List<String> violations(String dir, Predicate<References.Reference> forbidden) throws IOException {
        List<String> found = new ArrayList<>();
        List<Path> files = javaFiles(dir);
        assertTrue(files.size() > 3, "found only " + files.size() + " sources under " + dir + "; is the scan looking in the right place?");
        for (Path file : files) {
            for (References.Reference r : References.in(name(file), Files.readAllLines(file, StandardCharsets.UTF_8))) {
                if (forbidden.test(r)) {
                    found.add(r.toString());
                }
            }
        }
        return found;
    }

    private static List<Path> javaFiles(String dir) throws IOException {
        try (Stream<Path> all = Files.walk(SOURCES.resolve(dir))) {
            return all.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList());
        }
    }

    private static String name(Path file) {
        return ROOT.relativize(file).toString();
    }
}
