package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.Member;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The public surface of the client library is RP1 0.60's plus only the additions listed, each with its
 * reason, in api-additions.txt beside this test. Any other public or protected type or member in
 * rp1.rossum, rp1.rossum.event or rp1.rossum.request fails the test, and so does a listed addition
 * that no longer exists. An override adds nothing: the method is listed where it is first declared. A
 * type entry allows the whole type; a member entry is Type.member or Type.method(ParameterTypes).
 *
 * <p>Every other package of the library must be declared internal, here and in its package comment.
 * An internal package is not client API: RP1 0.60 has no such package, so no 0.60 program depends on
 * it, and its public types are public only so that the server can share the wire format with the
 * client library. Keeping them out of the three API packages is what leaves 0.60's surface as it is;
 * a new package that is neither API nor declared internal fails the test.
 */
class ApiAdditionsTest {
    private static final String ADDITIONS = "api-additions.txt";
    private static final List<String> PACKAGES = List.of("rp1.rossum", "rp1.rossum.event", "rp1.rossum.request");
    /** Packages that are not client API (see the class comment); their package comment begins "Internal:". */
    private static final List<String> INTERNAL = List.of("rp1.rossum.wire");

    /** The 0.60 types by qualified name, each with the keys of its members (see {@link ApiList#key}). */
    private final Map<String, Set<String>> original = new HashMap<>();

    @Test
    void everyPublicAdditionToTheOriginalApiIsListedWithItsReason() throws Exception {
        for (ApiList.Type t : ApiList.read()) {
            original.put(t.qualifiedName(), t.members.stream().map(ApiList::key).collect(Collectors.toSet()));
        }
        Map<String, String> allowed = allowedAdditions();
        Set<String> found = new TreeSet<>();
        for (Class<?> c : libraryTypes()) {
            found.addAll(additionsIn(c));
        }
        List<String> problems = new ArrayList<>();
        for (String addition : found) {
            if (!allowed.containsKey(addition) && !allowed.containsKey(typeOf(addition))) {
                problems.add("public addition not in " + ADDITIONS + ": " + addition);
            }
        }
        for (String entry : allowed.keySet()) {
            if (!found.contains(entry)) {
                problems.add(ADDITIONS + " lists what is not a public addition (any more): " + entry);
            }
        }
        if (!problems.isEmpty()) {
            fail(String.join("\n", problems));
        }
    }

    @Test
    void everyOtherPackageIsDeclaredInternal() throws Exception {
        Path root = classRoot();
        Set<String> packages = new TreeSet<>();
        try (Stream<Path> files = Files.walk(root)) {
            files.filter(p -> p.toString().endsWith(".class"))
                    .forEach(p -> packages.add(root.relativize(p.getParent()).toString().replace(p.getFileSystem().getSeparator(), ".")));
        }
        List<String> problems = new ArrayList<>();
        for (String pkg : packages) {
            if (!PACKAGES.contains(pkg) && !INTERNAL.contains(pkg)) {
                problems.add("package " + pkg + " is neither client API nor declared internal");
            }
        }
        String projectRoot = System.getProperty("rp1.root");
        assertNotNull(projectRoot, "system property rp1.root (the project directory) is not set");
        for (String pkg : INTERNAL) {
            Path info = Path.of(projectRoot, "rp1-rossum", "src", "main", "java", pkg.replace('.', '/'), "package-info.java");
            String text = Files.exists(info) ? Files.readString(info) : "";
            if (!text.contains("/**\n * Internal:")) {
                problems.add(info + ": an internal package's comment must begin \"Internal:\"");
            }
        }
        if (!problems.isEmpty()) {
            fail(String.join("\n", problems));
        }
    }

    /** The qualified type of a member entry ("p.Type.member(...)" gives "p.Type"). */
    private static String typeOf(String entry) {
        String head = entry.contains("(") ? entry.substring(0, entry.indexOf('(')) : entry;
        return head.contains(".") ? head.substring(0, head.lastIndexOf('.')) : head;
    }

    /** What {@code c} adds: the type itself if 0.60 has no such type, else its new members. */
    private List<String> additionsIn(Class<?> c) {
        String name = c.getName().replace('$', '.');
        Set<String> members = original.get(name);
        if (members == null) {
            return List.of(name);
        }
        List<String> added = new ArrayList<>();
        List<Member> declared = new ArrayList<>();
        declared.addAll(Arrays.asList(c.getDeclaredFields()));
        declared.addAll(Arrays.asList(c.getDeclaredConstructors()));
        declared.addAll(Arrays.asList(c.getDeclaredMethods()));
        for (Member m : declared) {
            if (m.isSynthetic() || !isVisible(m.getModifiers()) || (m instanceof Method && ((Method) m).isBridge())) {
                continue;
            }
            String key = key(m);
            if (!members.contains(key) && !(m instanceof Method && overridesKnown(c, (Method) m, key))) {
                added.add(name + "." + key);
            }
        }
        return added;
    }

    private static boolean isVisible(int modifiers) {
        return Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers);
    }

    private static String key(Member m) {
        if (m instanceof Field) {
            return m.getName();
        }
        Executable x = (Executable) m;
        String params = Arrays.stream(x.getParameterTypes()).map(Class::getSimpleName).collect(Collectors.joining(", "));
        String name = m instanceof Constructor ? m.getDeclaringClass().getSimpleName() : m.getName();
        return name + "(" + params + ")";
    }

    /**
     * Whether {@code m} overrides a method that a supertype already offers: one of the 0.60 API, of
     * the JDK, or an addition of ours, which is then listed once, where it is first declared.
     */
    private boolean overridesKnown(Class<?> c, Method m, String key) {
        for (Class<?> s : supertypes(c)) {
            Set<String> members = original.get(s.getName());
            if (members != null && members.contains(key) || Modifier.isPublic(s.getModifiers()) && declaresVisible(s, m)) {
                return true;
            }
        }
        return false;
    }

    private static boolean declaresVisible(Class<?> type, Method m) {
        try {
            return isVisible(type.getDeclaredMethod(m.getName(), m.getParameterTypes()).getModifiers());
        } catch (NoSuchMethodException e) {
            return false;
        }
    }

    /** Every proper supertype of {@code c}: superclasses and interfaces, transitively, and Object. */
    private static Set<Class<?>> supertypes(Class<?> c) {
        Set<Class<?>> all = new HashSet<>();
        List<Class<?>> todo = new ArrayList<>(List.of(c));
        while (!todo.isEmpty()) {
            Class<?> k = todo.remove(todo.size() - 1);
            if (k.getSuperclass() != null && all.add(k.getSuperclass())) {
                todo.add(k.getSuperclass());
            }
            for (Class<?> i : k.getInterfaces()) {
                if (all.add(i)) {
                    todo.add(i);
                }
            }
        }
        all.add(Object.class);
        return all;
    }

    /** The public types of the three packages (nested ones only if every enclosing type is public). */
    private static List<Class<?>> libraryTypes() throws IOException, URISyntaxException, ClassNotFoundException {
        Path root = classRoot();
        List<Class<?>> types = new ArrayList<>();
        for (String pkg : PACKAGES) {
            Path dir = root.resolve(pkg.replace('.', '/'));
            List<String> names;
            try (Stream<Path> files = Files.list(dir)) {
                names = files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".class"))
                        .map(n -> pkg + "." + n.substring(0, n.length() - ".class".length())).sorted()
                        .collect(Collectors.toList());
            }
            for (String name : names) {
                Class<?> c = Class.forName(name, false, RsBody.class.getClassLoader());
                if (isApiType(c)) {
                    types.add(c);
                }
            }
        }
        return types;
    }

    /** Where the library's classes are. */
    private static Path classRoot() throws URISyntaxException {
        return Path.of(RsBody.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    private static boolean isApiType(Class<?> c) {
        if (c.isAnonymousClass() || c.isLocalClass() || c.isSynthetic()) {
            return false;
        }
        for (Class<?> k = c; k != null; k = k.getEnclosingClass()) {
            if (!Modifier.isPublic(k.getModifiers())) {
                return false;
            }
        }
        return true;
    }

    /** The entries of api-additions.txt and their reasons; every entry must give one. */
    private static Map<String, String> allowedAdditions() throws IOException {
        Map<String, String> allowed = new TreeMap<>();
        try (InputStream in = ApiAdditionsTest.class.getResourceAsStream(ADDITIONS)) {
            if (in == null) {
                throw new IllegalStateException(ADDITIONS + " is not on the test class path");
            }
            BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            int lineNumber = 0;
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                lineNumber++;
                if (line.isBlank() || line.startsWith("#")) {
                    continue;
                }
                int dash = line.indexOf(" -- ");
                if (dash < 0 || line.substring(dash + 4).isBlank()) {
                    fail(ADDITIONS + ":" + lineNumber + ": an entry needs a reason after \" -- \": " + line);
                }
                allowed.put(line.substring(0, dash).trim(), line.substring(dash + 4).trim());
            }
        }
        return allowed;
    }
}
