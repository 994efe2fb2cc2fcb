package rp1.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.BiFunction;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The repository stands alone: every section of docs/behavior.md, docs/protocol.md or docs/guide.md
 * that the code, the tests, the properties files, the README or the docs cite exists there under that
 * number, nothing cites a numbered part of the original's user's guide (which is not in the
 * repository), and nothing reads or cites the original's material beside the repository, except the
 * tests that compare against the original's sample plans.
 */
class CitationsTest {
    private static final Path ROOT = Paths.get(System.getProperty("rp1.root", "."));

    @Test
    void everyCitedSectionExistsInDocs() throws IOException {
        Map<String, Set<String>> sections = new HashMap<>();
        for (String doc : List.of("behavior.md", "protocol.md", "guide.md")) {
            sections.put(doc, Citations.sections(read(ROOT.resolve("docs").resolve(doc))));
        }
        List<Citations.Citation> citations = new ArrayList<>();
        for (Path file : citingFiles()) {
            citations.addAll(Citations.in(name(file), read(file)));
        }
        assertTrue(citations.size() > 100, "found only " + citations.size() + " citations; is the scan looking in the right place?");
        assertEquals("", String.join("\n", Citations.missing(citations, sections)), "citations of sections that do not exist");
    }

    @Test
    void nothingRefersToTheOriginalsMaterialButTheSamplePlanTests() throws IOException {
        assertNoneFound(Citations::sharedReferences, "references to the material beside the repository");
    }

    @Test
    void nothingCitesANumberedPartOfTheOriginalsUsersGuide() throws IOException {
        assertNoneFound(Citations::originalGuideReferences,
                "citations of the original's user's guide: cite docs/ or say it in place");
    }

    /** Runs {@code finder} (file name, lines: findings) over every citing file; expects no findings. */
    private static void assertNoneFound(BiFunction<String, List<String>, List<String>> finder, String message)
            throws IOException {
        List<String> found = new ArrayList<>();
        for (Path file : citingFiles()) {
            found.addAll(finder.apply(name(file), read(file)));
        }
        assertEquals("", String.join("\n", found), message);
    }

    @Test
    void aNumberedReferenceToTheOriginalsGuideIsReportedWithItsFileAndLine() {
        String guide = "Gu" + "ide";
        List<String> lines = List.of(
                "/**",
                " * ClientZero (User's " + guide + " section 4.6, Figures 8 and 9) and a backlog (the user's",
                " * " + guide.toLowerCase() + "'s heartbeat backlog, section 5.4.1.1), as the original " + guide.toLowerCase() + " recommends (its",
                " * section 4.1.1); the demo (User's " + guide + " Table 4).",
                " * The original's user's " + guide.toLowerCase() + " documents kilometers. See docs/guide.md section 2.",
                " */");
        assertEquals(List.of("Z.java:2: " + lines.get(1).trim(), "Z.java:3: " + lines.get(2).trim(),
                "Z.java:4: " + lines.get(3).trim()), Citations.originalGuideReferences("Z.java", lines));
    }

    @Test
    void aCitationOfAMissingSectionIsReportedWithItsFileAndLine() {
        List<String> lines = List.of(
                "/**",
                " * Motion (behavior" + ".md section 5.4) and the header (docs/protocol" + ".md section 3.2).",
                " * Quirks: behavior" + ".md sections 6.2 and 99.1, and behavior" + ".md",
                " * section 42.",
                " */");
        List<String> cited = new ArrayList<>();
        List<String> documents = new ArrayList<>();
        for (Citations.Citation c : Citations.in("X.java", lines)) {
            cited.add(c.where() + " " + c.section());
            documents.add(c.document());
        }
        assertEquals(List.of("X.java:2 5.4", "X.java:2 3.2", "X.java:3 6.2", "X.java:3 99.1", "X.java:3 42"), cited);
        assertEquals(List.of("behavior.md", "protocol.md", "behavior.md", "behavior.md", "behavior.md"), documents);
        Map<String, Set<String>> sections = Map.of("behavior.md", Set.of("5.4", "6.2"), "protocol.md", Set.of("3.2"));
        assertEquals(List.of("X.java:3: docs/behavior.md has no section 99.1", "X.java:3: docs/behavior.md has no section 42"),
                Citations.missing(Citations.in("X.java", lines), sections));
    }

    @Test
    void numberedHeadingsAreTheSections() {
        assertEquals(Set.of("4", "4.2", "6.0"), Citations.sections(List.of(
                "# Title", "## 4. Scheduler", "text 4.3", "### 4.2 Clock", "### 6.0 Prefix", "## Appendix")));
    }

    @Test
    void onlyTheOriginalsSamplePlansAndThePeerSimulatorsMayBeReadFromBesideTheRepository() {
        String shared = ".." + "/shared/";
        List<String> lines = List.of(
                "Path plans = root.resolve(\"" + shared + Citations.ORIGINAL_SAMPLE_PLANS + "\");",
                "Path spec = root.resolve(\"" + shared + "spec/protocol.md\");",
                "Path api = Paths.get(root, \"..\", \"" + "shared\", \"spec\");",
                "Path stage = root.resolve(\"" + shared + Citations.PEERS + "/stage-4.3.0-src.tar.gz\");");
        assertEquals(List.of("Y.java:2: " + lines.get(1), "Y.java:3: " + lines.get(2)),
                Citations.sharedReferences("Y.java", lines));
    }

    /** Java sources of every module, the properties files, the README and the docs. */
    private static List<Path> citingFiles() throws IOException {
        List<Path> files = new ArrayList<>();
        try (Stream<Path> modules = Files.list(ROOT)) {
            for (Path module : modules.filter(p -> p.getFileName().toString().startsWith("rp1-")).sorted()
                    .collect(Collectors.toList())) {
                files.addAll(list(module.resolve("src"), "*.java"));
            }
        }
        files.addAll(list(ROOT.resolve("Properties"), "*.ini"));
        files.add(ROOT.resolve("README.md"));
        files.addAll(list(ROOT.resolve("docs"), "*.md"));
        return files;
    }

    private static List<Path> list(Path dir, String glob) throws IOException {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        String suffix = glob.substring(1);
        try (Stream<Path> all = Files.walk(dir)) {
            return all.filter(p -> p.getFileName().toString().endsWith(suffix)).sorted().collect(Collectors.toList());
        }
    }

    private static String name(Path file) {
        return ROOT.relativize(file).toString();
    }

    private static List<String> read(Path file) throws IOException {
        return Files.readAllLines(file, StandardCharsets.UTF_8);
    }
}
