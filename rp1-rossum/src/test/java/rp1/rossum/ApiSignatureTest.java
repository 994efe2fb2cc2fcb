package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;

import org.junit.jupiter.api.Test;

/**
 * Source compatibility: every public type of RP1 0.60 and every public or protected member of it (as
 * listed in api-0.60.txt beside this test) exists here with the same kind, superclass, interfaces,
 * modifiers, parameter and return types, checked exceptions and constant values. Programs written
 * for the original compile against this library only if this holds.
 */
class ApiSignatureTest {
    private final List<String> problems = new ArrayList<>();

    @Test
    void everyTypeAndMemberOfTheOriginalApiExists() {
        int types = 0;
        int members = 0;
        for (ApiList.Type type : ApiList.read()) {
            Class<?> c = checkType(type.pkg, type.declaration);
            types++;
            for (String line : type.members) {
                if (c != null) {
                    checkMember(c, line);
                }
                members++;
            }
        }
        assertEquals(115, types, "types read from api-0.60.txt");
        assertEquals(965, members, "members read from api-0.60.txt");
        if (!problems.isEmpty()) {
            fail(problems.size() + " incompatibilities with the RP1 0.60 API (" + types + " types, " + members
                    + " members checked):\n" + String.join("\n", problems));
        }
    }

    private Class<?> checkType(String pkg, Matcher t) {
        String name = pkg + "." + t.group(3);
        Class<?> c;
        try {
            c = Class.forName(name);
        } catch (ClassNotFoundException e) {
            problems.add("missing type " + name);
            return null;
        }
        boolean isInterface = t.group(2).equals("interface");
        if (c.isInterface() != isInterface) {
            problems.add(name + ": expected " + t.group(2));
        }
        if (!Modifier.isPublic(c.getModifiers())) {
            problems.add(name + ": not public");
        }
        if (!isInterface && (t.group(1) != null) != Modifier.isAbstract(c.getModifiers())) {
            problems.add(name + ": abstract should be " + (t.group(1) != null));
        }
        if (t.group(4) != null) {
            if (isInterface) {
                checkInterfaces(c, t.group(4));
            } else if (c.getSuperclass() == null || !c.getSuperclass().getSimpleName().equals(ApiList.simple(t.group(4)))) {
                problems.add(name + ": superclass should be " + t.group(4) + ", is " + c.getSuperclass());
            }
        }
        if (t.group(5) != null) {
            checkInterfaces(c, t.group(5));
        }
        return c;
    }

    private void checkInterfaces(Class<?> c, String list) {
        for (String i : list.split(",")) {
            boolean found = Arrays.stream(c.getInterfaces()).anyMatch(x -> x.getSimpleName().equals(ApiList.simple(i.trim())));
            if (!found) {
                problems.add(c.getName() + ": should directly implement/extend " + i.trim());
            }
        }
    }

    private void checkMember(Class<?> c, String line) {
        Matcher e = ApiList.EXECUTABLE.matcher(line);
        if (e.matches()) {
            checkExecutable(c, e, line);
            return;
        }
        Matcher f = ApiList.FIELD.matcher(line);
        if (f.matches()) {
            checkField(c, f, line);
            return;
        }
        problems.add("unparsed api-0.60.txt line in " + c.getSimpleName() + ": " + line);
    }

    private void checkField(Class<?> c, Matcher f, String line) {
        Field field = findField(c, f.group(4));
        String where = c.getName() + "." + f.group(4);
        if (field == null) {
            problems.add("missing field " + where);
            return;
        }
        int m = field.getModifiers();
        checkVisibility(where, f.group(1), m);
        String mods = f.group(2);
        if (mods.contains("static") != Modifier.isStatic(m) || mods.contains("final") != Modifier.isFinal(m)) {
            problems.add(where + ": modifiers should be '" + mods.trim() + "': " + line);
        }
        if (!typeMatches(field.getType(), f.group(3))) {
            problems.add(where + ": type should be " + f.group(3) + ", is " + field.getType().getSimpleName());
        }
        if (f.group(5) != null) {
            checkConstant(where, field, f.group(5));
        }
    }

    private void checkConstant(String where, Field field, String expected) {
        try {
            field.setAccessible(true);
            Object value = field.get(null);
            String text = expected.endsWith("d") ? expected.substring(0, expected.length() - 1) : expected;
            boolean same = value instanceof Double
                    ? (Double) value == Double.parseDouble(text)
                    : String.valueOf(value).equals(text);
            if (!same) {
                problems.add(where + ": value should be " + expected + ", is " + value);
            }
        } catch (ReflectiveOperationException | RuntimeException ex) {
            problems.add(where + ": cannot read constant: " + ex);
        }
    }

    private static Field findField(Class<?> c, String name) {
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            try {
                return k.getDeclaredField(name);
            } catch (NoSuchFieldException ignored) {
                // look in the superclass
            }
        }
        return null;
    }

    private void checkExecutable(Class<?> c, Matcher e, String line) {
        String returnType = e.group(3);
        String name = e.group(4);
        String[] params = e.group(5).trim().isEmpty() ? new String[0] : e.group(5).split(",\\s*");
        boolean isConstructor = returnType == null;
        String where = c.getName() + "." + name + "(" + e.group(5) + ")";
        Executable x = isConstructor ? findConstructor(c, params) : findMethod(c, name, params);
        if (x == null) {
            problems.add("missing " + (isConstructor ? "constructor " : "method ") + where);
            return;
        }
        int m = x.getModifiers();
        checkVisibility(where, e.group(1), m);
        String mods = e.group(2);
        if (mods.contains("static") != Modifier.isStatic(m)) {
            problems.add(where + ": static should be " + mods.contains("static"));
        }
        if (mods.contains("abstract") && !Modifier.isAbstract(m)) {
            problems.add(where + ": should be abstract");
        }
        if (mods.contains("final") != Modifier.isFinal(m)) {
            problems.add(where + ": final should be " + mods.contains("final"));
        }
        if (!isConstructor && !typeMatches(((Method) x).getReturnType(), returnType)) {
            problems.add(where + ": return type should be " + returnType + ", is " + ((Method) x).getReturnType().getSimpleName());
        }
        checkThrows(where, x, e.group(6));
    }

    /** Callers must be able to catch what the original declared, and see no new checked exception. */
    private void checkThrows(String where, Executable x, String declared) {
        List<String> expected = declared == null ? List.of() : Arrays.asList(declared.split(",\\s*"));
        for (String ex : expected) {
            if (ex.equals("ArithmeticException")) {
                continue;
            }
            boolean covered = Arrays.stream(x.getExceptionTypes()).anyMatch(t -> isSubclassNamed(t, ex));
            if (!covered) {
                problems.add(where + ": should declare throws " + ex);
            }
        }
        for (Class<?> t : x.getExceptionTypes()) {
            if (RuntimeException.class.isAssignableFrom(t) || Error.class.isAssignableFrom(t)) {
                continue;
            }
            boolean allowed = expected.stream().anyMatch(ex -> isSubclassNamed(t, ex));
            if (!allowed) {
                problems.add(where + ": declares a checked exception the original does not: " + t.getSimpleName());
            }
        }
    }

    private static boolean isSubclassNamed(Class<?> t, String name) {
        for (Class<?> k = t; k != null; k = k.getSuperclass()) {
            if (k.getSimpleName().equals(name)) {
                return true;
            }
        }
        return false;
    }

    private void checkVisibility(String where, String visibility, int m) {
        boolean ok = visibility.equals("public") ? Modifier.isPublic(m) : Modifier.isProtected(m) || Modifier.isPublic(m);
        if (!ok) {
            problems.add(where + ": should be " + visibility);
        }
    }

    private static Constructor<?> findConstructor(Class<?> c, String[] params) {
        for (Constructor<?> k : c.getDeclaredConstructors()) {
            if (paramsMatch(k.getParameterTypes(), params)) {
                return k;
            }
        }
        return null;
    }

    private static Method findMethod(Class<?> c, String name, String[] params) {
        List<Class<?>> search = new ArrayList<>();
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            search.add(k);
        }
        search.addAll(Arrays.asList(c.getInterfaces()));
        for (Class<?> k : search) {
            for (Method m : k.getDeclaredMethods()) {
                if (m.getName().equals(name) && !m.isSynthetic() && !m.isBridge() && paramsMatch(m.getParameterTypes(), params)) {
                    return m;
                }
            }
        }
        return null;
    }

    private static boolean paramsMatch(Class<?>[] actual, String[] expected) {
        if (actual.length != expected.length) {
            return false;
        }
        for (int i = 0; i < actual.length; i++) {
            if (!typeMatches(actual[i], expected[i].trim())) {
                return false;
            }
        }
        return true;
    }

    private static boolean typeMatches(Class<?> actual, String expected) {
        return actual.getSimpleName().equals(ApiList.simple(expected));
    }
}
