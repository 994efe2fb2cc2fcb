package rp1.docs;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The code blocks of docs/guide.md: its Java examples (every block that starts with
 * {@code package mybot;}) and the blocks marked {@code <!-- guide: NAME -->} on the line before them
 * (a floor plan, what an example prints).
 */
final class GuideText {
    private static final Pattern BLOCK = Pattern.compile("```(\\w*)\n(.*?)```", Pattern.DOTALL);
    private final String text;

    private GuideText(String text) {
        this.text = text;
    }

    static GuideText read(Path root) throws IOException {
        return new GuideText(new String(Files.readAllBytes(root.resolve("docs/guide.md")), StandardCharsets.UTF_8));
    }

    /** The Java examples, in the order they appear. */
    List<String> javaExamples() {
        List<String> sources = new ArrayList<>();
        Matcher m = BLOCK.matcher(text);
        while (m.find()) {
            if (m.group(1).equals("java") && m.group(2).startsWith("package mybot;")) {
                sources.add(m.group(2));
            }
        }
        return sources;
    }

    /** The contents of the code block right after {@code <!-- guide: name -->}. */
    String block(String name) {
        String marker = "<!-- guide: " + name + " -->\n";
        int at = text.indexOf(marker);
        if (at < 0) {
            throw new AssertionError("docs/guide.md has no block marked " + marker.trim());
        }
        Matcher m = BLOCK.matcher(text);
        if (!m.find(at + marker.length()) || m.start() != at + marker.length()) {
            throw new AssertionError("no code block right after " + marker.trim() + " in docs/guide.md");
        }
        return m.group(2);
    }

    /** The public class a Java example declares. */
    static String className(String source) {
        Matcher m = Pattern.compile("public (?:final )?class (\\w+)").matcher(source);
        if (!m.find()) {
            throw new AssertionError("a guide example without a public class:\n" + source);
        }
        return m.group(1);
    }
}
