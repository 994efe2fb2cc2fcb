package rp1.rossum;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The RP1 0.60 API as listed in {@code api-0.60.txt} (kept beside the tests): every public type of
 * the three client packages with its public and protected members, one Java declaration a line,
 * types by simple name. A {@code package} line starts each package; {@code #} starts a comment.
 */
final class ApiList {
    static final Pattern TYPE = Pattern.compile(
            "^public (abstract )?(class|interface) (\\w+)(?: extends ([\\w.]+))?(?: implements ([\\w.,]+))? \\{$");
    static final Pattern FIELD = Pattern.compile(
            "^(public|protected) ((?:static |final )*)([\\w.<>\\[\\]]+) (\\w+)(?: = (.+))?;$");
    static final Pattern EXECUTABLE = Pattern.compile(
            "^(public|protected) ((?:static |final |abstract |synchronized )*)(?:([\\w.<>\\[\\]]+) )?(\\w+)\\(([^)]*)\\)(?: throws ([\\w, ]+))?;$");
    private static final Pattern PACKAGE = Pattern.compile("^package ([\\w.]+);$");
    private static final String RESOURCE = "api-0.60.txt";

    /** A type of the list: its package, its declaration (matched by {@link #TYPE}) and its member lines. */
    static final class Type {
        final String pkg;
        final Matcher declaration;
        final List<String> members = new ArrayList<>();

        Type(String pkg, Matcher declaration) {
            this.pkg = pkg;
            this.declaration = declaration;
        }

        String simpleName() {
            return declaration.group(3);
        }

        String qualifiedName() {
            return pkg + "." + simpleName();
        }
    }

    private ApiList() {
    }

    /** The types of the list, in listed order. */
    static List<Type> read() {
        List<Type> types = new ArrayList<>();
        String pkg = null;
        Type current = null;
        for (String raw : lines()) {
            String line = raw.trim();
            Matcher p = PACKAGE.matcher(line);
            Matcher t = TYPE.matcher(line);
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            } else if (p.matches()) {
                pkg = p.group(1);
            } else if (t.matches()) {
                current = new Type(pkg, t);
                types.add(current);
            } else if (line.equals("}")) {
                current = null;
            } else if (current != null) {
                current.members.add(line);
            } else {
                throw new IllegalStateException(RESOURCE + ": a line outside any type: " + line);
            }
        }
        return types;
    }

    private static List<String> lines() {
        try (InputStream in = ApiList.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException(RESOURCE + " is not on the test class path");
            }
            List<String> lines = new ArrayList<>();
            BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                lines.add(line);
            }
            return lines;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * A member line as a key independent of modifiers and return type: {@code name} for a field,
     * {@code name(Type, Type)} for a method or constructor, parameter types by simple name without
     * type arguments.
     */
    static String key(String memberLine) {
        Matcher e = EXECUTABLE.matcher(memberLine);
        if (e.matches()) {
            List<String> params = new ArrayList<>();
            for (String p : e.group(5).trim().isEmpty() ? new String[0] : e.group(5).split(",")) {
                params.add(simple(p.trim()));
            }
            return e.group(4) + "(" + String.join(", ", params) + ")";
        }
        Matcher f = FIELD.matcher(memberLine);
        if (f.matches()) {
            return f.group(4);
        }
        throw new IllegalArgumentException("not a member declaration: " + memberLine);
    }

    /** A type name without type arguments and without its qualifier. */
    static String simple(String name) {
        String erased = name.replaceAll("<.*>", "");
        int dot = erased.lastIndexOf('.');
        return dot < 0 ? erased : erased.substring(dot + 1);
    }
}
