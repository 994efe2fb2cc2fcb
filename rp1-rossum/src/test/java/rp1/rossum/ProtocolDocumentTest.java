package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * docs/protocol.md shows what the code does: every worked example in it is byte for byte what our
 * encoders emit, decodes back to the values it describes, and is matched to a builder in
 * {@link ProtocolExamples} by its name; every builder there has its example in the document.
 */
class ProtocolDocumentTest {
    private static final Pattern MARKER = Pattern.compile("<!-- example: ([a-z0-9-]+) -->");
    private static final Pattern HEX_LINE = Pattern.compile("[0-9a-f ]*");

    private static Map<String, byte[]> documentExamples() throws IOException {
        String root = System.getProperty("rp1.root");
        assertNotNull(root, "system property rp1.root (the project directory) is not set");
        Path doc = Paths.get(root, "docs", "protocol.md");
        return parse(new String(Files.readAllBytes(doc), StandardCharsets.UTF_8));
    }

    @TestFactory
    Stream<DynamicTest> everyExampleInTheDocumentIsWhatTheCodeEmitsAndDecodesBack() throws IOException {
        Map<String, ProtocolExamples.Example> builders = ProtocolExamples.all();
        return documentExamples().entrySet().stream().map(e -> dynamicTest(e.getKey(), () -> {
            ProtocolExamples.Example example = builders.get(e.getKey());
            assertNotNull(example, "no builder in ProtocolExamples for the example \"" + e.getKey() + "\"");
            assertEquals(Hex.of(e.getValue()), Hex.of(example.builder().build()), e.getKey());
            example.check().check(e.getValue());
        }));
    }

    @Test
    void everyBuilderHasItsExampleInTheDocument() throws IOException {
        List<String> missing = new ArrayList<>(ProtocolExamples.all().keySet());
        missing.removeAll(documentExamples().keySet());
        assertEquals(List.of(), missing, "examples missing from docs/protocol.md");
    }

    @Test
    void aHexBlockWithoutANameIsRejected() {
        String doc = "text\n```hex\n00000001\n```\n";
        assertThrows(IllegalArgumentException.class, () -> parse(doc));
    }

    @Test
    void aNameMustBeFollowedByAHexBlockOfHexDigits() {
        assertThrows(IllegalArgumentException.class, () -> parse("<!-- example: x -->\ntext\n"));
        assertThrows(IllegalArgumentException.class, () -> parse("<!-- example: x -->\n```hex\n0000 00zz\n```\n"));
        assertThrows(IllegalArgumentException.class, () -> parse("<!-- example: x -->\n```hex\n000\n```\n"));
        assertThrows(IllegalArgumentException.class, () -> parse("<!-- example: x -->\n```hex\n0000\n"));
    }

    @Test
    void commentsAndGroupingAreIgnored() {
        Map<String, byte[]> examples = parse("<!-- example: x -->\n```hex\n0000 0001  # one\n\n02 # two # more\n```\n");
        assertEquals("00000001 02", Hex.of(examples.get("x")));
    }

    /**
     * The examples of a document: each is a line {@code <!-- example: NAME -->} directly followed by a
     * fenced {@code hex} block whose lines hold hex digits grouped by spaces, each optionally followed
     * by a {@code #} comment. A hex block without a name, a name without a block, a repeated name or
     * anything but hex digits in a block is an error, so that no example goes unchecked.
     */
    static Map<String, byte[]> parse(String document) {
        String[] lines = document.split("\n", -1);
        Map<String, byte[]> examples = new LinkedHashMap<>();
        for (int i = 0; i < lines.length; i++) {
            Matcher marker = MARKER.matcher(lines[i].trim());
            if (lines[i].trim().equals("```hex")) {
                throw new IllegalArgumentException("line " + (i + 1) + ": hex block without an example name");
            }
            if (!marker.matches()) {
                continue;
            }
            String name = marker.group(1);
            if (i + 1 >= lines.length || !lines[i + 1].trim().equals("```hex")) {
                throw new IllegalArgumentException("line " + (i + 2) + ": example " + name + " is not followed by ```hex");
            }
            StringBuilder digits = new StringBuilder();
            i += 2;
            for (; i < lines.length && !lines[i].trim().equals("```"); i++) {
                String data = lines[i].replaceFirst("#.*", "").trim();
                if (!HEX_LINE.matcher(data).matches()) {
                    throw new IllegalArgumentException("line " + (i + 1) + ": not hex digits: " + data);
                }
                digits.append(data.replace(" ", ""));
            }
            if (i >= lines.length) {
                throw new IllegalArgumentException("example " + name + ": hex block not closed");
            }
            if (examples.put(name, Hex.bytes(digits.toString())) != null) {
                throw new IllegalArgumentException("example " + name + " appears twice");
            }
        }
        return examples;
    }
}
