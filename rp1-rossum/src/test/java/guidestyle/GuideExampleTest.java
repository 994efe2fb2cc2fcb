package guidestyle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * The example client in docs/guide.md compiles: {@link GuideBumper} is that example with only its
 * package and class name changed, and this test fails if the two drift apart.
 */
class GuideExampleTest {

    @Test
    void theGuidesExampleClientIsTheCompiledGuideBumper() throws Exception {
        Path root = Paths.get(System.getProperty("rp1.root", "."));
        String guide = new String(Files.readAllBytes(root.resolve("docs/guide.md")), StandardCharsets.UTF_8);
        Matcher m = Pattern.compile("```java\n(package mybot;.*?)```", Pattern.DOTALL).matcher(guide);
        assertTrue(m.find(), "docs/guide.md has a java example starting with 'package mybot;'");
        String expected = m.group(1)
                .replace("package mybot;", "package guidestyle;\n\n"
                        + "// The example client of docs/guide.md section 3, kept here so that it must compile.")
                .replace("Bumper", "GuideBumper");
        String actual = new String(Files.readAllBytes(
                root.resolve("rp1-rossum/src/test/java/guidestyle/GuideBumper.java")), StandardCharsets.UTF_8);
        assertEquals(expected, actual);
    }
}
