package rp1.architecture;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds the qualified names a Java source file refers to in code (its imports, static and wildcard
 * ones included, and names written out in full), each with "name:line". Comments and string and
 * character literals are left out, so a javadoc mentioning a class or a {@code "-Djava.awt.headless"}
 * argument is not a reference. Textual, not a compiler: a class of the same package needs no import
 * and is not seen, which is why the rules are about other packages.
 */
final class References {
    /** A dotted name of at least two parts whose first part is a lower-case package name. */
    private static final Pattern QUALIFIED = Pattern.compile("\\b(?:java|javax|rp1)(?:\\.\\w+)+(?:\\.\\*)?");

    /** One reference: the qualified name as written and where. */
    record Reference(String name, String where) {
        /** Whether the name is {@code pkg} itself or lies in it or below it. */
        boolean isIn(String pkg) {
            return name.equals(pkg) || name.startsWith(pkg + ".");
        }

        @Override
        public String toString() {
            return where + ": " + name;
        }
    }

    private References() {
    }

    /** The references in the code of {@code lines} (a whole file) named {@code file}. */
    static List<Reference> in(String file, List<String> lines) {
        List<Reference> found = new ArrayList<>();
        List<String> code = codeOnly(lines);
        for (int i = 0; i < code.size(); i++) {
            String line = code.get(i);
            if (line.trim().startsWith("package ")) {
                continue;
            }
            Matcher m = QUALIFIED.matcher(line);
            while (m.find()) {
                found.add(new Reference(m.group(), file + ":" + (i + 1)));
            }
        }
        return found;
    }

    /**
     * The lines with comments and literals blanked out (line numbers kept). Text blocks are not
     * handled; the sources have none that names a class.
     */
    static List<String> codeOnly(List<String> lines) {
        List<String> out = new ArrayList<>();
        boolean inBlock = false;
        for (String line : lines) {
            StringBuilder b = new StringBuilder();
            int i = 0;
            while (i < line.length()) {
                char c = line.charAt(i);
                if (inBlock) {
                    if (line.startsWith("*/", i)) {
                        inBlock = false;
                        i += 2;
                    } else {
                        i++;
                    }
                } else if (line.startsWith("/*", i)) {
                    inBlock = true;
                    i += 2;
                } else if (line.startsWith("//", i)) {
                    break;
                } else if (c == '"' || c == '\'') {
                    i = endOfLiteral(line, i, c);
                    b.append(' ');
                } else {
                    b.append(c);
                    i++;
                }
            }
            out.add(b.toString());
        }
        return out;
    }

    private static int endOfLiteral(String line, int start, char quote) {
        int i = start + 1;
        while (i < line.length() && line.charAt(i) != quote) {
            i += line.charAt(i) == '\\' ? 2 : 1;
        }
        return i + 1;
    }
}
