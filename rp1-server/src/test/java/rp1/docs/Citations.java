package rp1.docs;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds the places where a file refers to the project's reference documents ("behavior.md section
 * 5.4", "protocol.md sections 6.2 and 6.3", "behavior.md §9", "behavior.md 2.2", "guide.md section 2",
 * with or without {@code docs/}), to the directory of the original's material beside the repository,
 * and to a numbered part of the original's user's guide, which is not in the repository. A citation
 * broken across two lines, as javadoc wraps them, is found on the line where it begins.
 */
final class Citations {
    private static final String NUMBER = "(\\d+(?:\\.\\d+)*)";
    private static final Pattern CITATION = Pattern.compile(
            "(behavior|protocol|guide)\\.md,?\\s+(?:(?:sections?|§)\\s*)?" + NUMBER + "(?:\\s+and\\s+" + NUMBER + ")?");
    /** The shared folder beside the repository, as a path or as path elements; group 1 is what follows. */
    private static final Pattern SHARED = Pattern.compile(
            "\\.\\.(?:/|\"\\s*,\\s*\")shared(?:/|\"\\s*,\\s*\")?([\\w.-]*)");
    /**
     * The original's user's guide named ("user's guide", "original guide", any case), then within the
     * same sentence the word section, figure or table (or §) and a number.
     */
    private static final Pattern ORIGINAL_GUIDE = Pattern.compile(
            "(?i)\\b(?:user'?s|original'?s?)\\s+guide\\b[^.;]{0,80}?\\b(?:sections?|figures?|tables?|§)\\s*\\d");
    /** What tests may read from there: the original's sample plans, skipped when absent. */
    static final String ORIGINAL_SAMPLE_PLANS = "rp1-0.60-floorplans";
    /**
     * The peer simulators (not the original's material): tests read Stage's map images from its source
     * archive, skipped when absent, and docs/performance.md says where its figures come from.
     */
    static final String PEERS = "peers";
    private static final Pattern HEADING = Pattern.compile("^#{2,4}\\s+" + NUMBER + "\\.?\\s");
    /** What may start a continuation line in code comments, properties files and tables. */
    private static final Pattern CONTINUATION = Pattern.compile("^\\s*(?:\\*|//|#|\\|)?\\s*");

    /** One cited section. */
    record Citation(String document, String section, String where) {
    }

    private Citations() {
    }

    /**
     * The citations in {@code lines} of the file {@code name}, each with "name:line" (from 1).
     */
    static List<Citation> in(String name, List<String> lines) {
        List<Citation> found = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            Matcher m = CITATION.matcher(withNextLine(lines, i));
            while (m.find() && m.start() < line.length()) {
                String where = name + ":" + (i + 1);
                found.add(new Citation(m.group(1) + ".md", m.group(2), where));
                if (m.group(3) != null) {
                    found.add(new Citation(m.group(1) + ".md", m.group(3), where));
                }
            }
        }
        return found;
    }

    /**
     * The citations whose section is not among the {@code sections} of their document, as
     * "name:line: docs/DOC has no section N".
     */
    static List<String> missing(List<Citation> citations, Map<String, Set<String>> sections) {
        List<String> missing = new ArrayList<>();
        for (Citation c : citations) {
            if (!sections.getOrDefault(c.document(), Set.of()).contains(c.section())) {
                missing.add(c.where() + ": docs/" + c.document() + " has no section " + c.section());
            }
        }
        return missing;
    }

    /**
     * The places in {@code lines} that refer to the material beside the repository, other than to the
     * original's sample plans or the peer simulators, as "name:line: text".
     */
    static List<String> sharedReferences(String name, List<String> lines) {
        List<String> found = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            Matcher m = SHARED.matcher(lines.get(i));
            while (m.find()) {
                if (!m.group(1).equals(ORIGINAL_SAMPLE_PLANS) && !m.group(1).equals(PEERS)) {
                    found.add(name + ":" + (i + 1) + ": " + lines.get(i).trim());
                }
            }
        }
        return found;
    }

    /**
     * The places in {@code lines} that cite a section, figure or table of the original's user's guide,
     * as "name:line: text": a reader of the repository cannot look them up, so the code cites docs/ or
     * says the thing in place.
     */
    static List<String> originalGuideReferences(String name, List<String> lines) {
        List<String> found = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            Matcher m = ORIGINAL_GUIDE.matcher(withNextLine(lines, i));
            if (m.find() && m.start() < lines.get(i).length()) {
                found.add(name + ":" + (i + 1) + ": " + lines.get(i).trim());
            }
        }
        return found;
    }

    /** The section numbers of a markdown document's numbered headings ("## 4. Title", "### 4.2 Title"). */
    static Set<String> sections(List<String> markdown) {
        Set<String> numbers = new LinkedHashSet<>();
        for (String line : markdown) {
            Matcher m = HEADING.matcher(line);
            if (m.find()) {
                numbers.add(m.group(1));
            }
        }
        return numbers;
    }

    private static String withNextLine(List<String> lines, int i) {
        if (i + 1 >= lines.size()) {
            return lines.get(i);
        }
        String next = CONTINUATION.matcher(lines.get(i + 1)).replaceFirst("");
        return lines.get(i) + " " + next;
    }
}
