package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Every public type of the client API ({@code rp1.rossum}, {@code .event}, {@code .request}) has a
 * class comment saying what it is for, and each package has a description, so that the javadoc
 * ({@code gradle apiDocs}) documents the whole API.
 */
class ApiJavadocTest {
    private static final String[] PACKAGES = {"rp1/rossum", "rp1/rossum/event", "rp1/rossum/request"};
    /** A javadoc comment, optional annotations, then a public top-level type declaration. */
    private static final Pattern DOCUMENTED = Pattern.compile(
            "/\\*\\*\\s*\\*?\\s*\\w(?:(?!\\*/).)*\\*/\\s*(?:@\\w+(?:\\([^)]*\\))?\\s*)*"
                    + "^public\\s+(?:abstract\\s+|final\\s+)*(?:class|interface|enum|record)\\s",
            Pattern.DOTALL | Pattern.MULTILINE);
    private static final Pattern PUBLIC_TYPE = Pattern.compile(
            "(?m)^public\\s+(?:abstract\\s+|final\\s+)*(?:class|interface|enum|record)\\s");

    private static Path sources() {
        String root = System.getProperty("rp1.root");
        assertNotNull(root, "system property rp1.root (the project directory) is not set");
        return Paths.get(root, "rp1-rossum", "src", "main", "java");
    }

    @Test
    void everyPublicTypeHasAClassComment() throws IOException {
        List<String> undocumented = new ArrayList<>();
        int publicTypes = 0;
        for (String pkg : PACKAGES) {
            try (Stream<Path> files = Files.list(sources().resolve(pkg))) {
                for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                    String source = new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
                    if (!PUBLIC_TYPE.matcher(source).find()) {
                        continue;
                    }
                    publicTypes++;
                    if (!DOCUMENTED.matcher(source).find()) {
                        undocumented.add(pkg + "/" + f.getFileName());
                    }
                }
            }
        }
        assertFalse(publicTypes < 100, "found only " + publicTypes + " public types; wrong source directory?");
        assertEquals(List.of(), undocumented, "public types without a class comment");
    }

    @Test
    void everyApiPackageHasADescription() {
        for (String pkg : PACKAGES) {
            Path info = sources().resolve(pkg).resolve("package-info.java");
            assertTrue(Files.isRegularFile(info), "missing " + info);
        }
    }
}
