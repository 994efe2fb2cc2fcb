package rp1.simulator.batch;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * Whether any class in a robot's folders and jars can keep state in a static field, read from the
 * class files without loading them. A sweep's runs in one process share the robot's classes when none
 * can: a class is then the same in every run whether it is loaded anew or not, and loading it anew for
 * each run only costs (defining and verifying its classes, linking its lambdas, running its code in
 * the interpreter again: 8 % of a 64-run bumper sweep's wall time).
 *
 * <p>A static field holds no state a run could change if it is final and holds a primitive or a
 * string, or is one of the fields the Java compiler makes for enums (the constants of an enum whose
 * own fields are such values, and the array of them) and for switches on enums. Anything else (a
 * final array, list or random source included) counts as state. A class whose file cannot be read
 * counts as state too, and so does one that calls {@code RsMotion.getNewContinuityID()}, whose counter
 * is the caller's class loader's.
 */
final class StaticState {
    private static final int ACC_STATIC = 0x0008;
    private static final int ACC_FINAL = 0x0010;
    private static final int ACC_SYNTHETIC = 0x1000;
    private static final int ACC_ENUM = 0x4000;

    private StaticState() {
    }

    /**
     * The first class field found that can keep state, as "CLASS.FIELD", among the classes in
     * {@code locations} (folders and jars); empty if none can. More than {@code maxClasses} classes
     * count as state: looking through them all would cost more than it could save.
     */
    static Optional<String> find(List<URL> locations, int maxClasses) {
        return first(locations, maxClasses, Optional.of("one of more than " + maxClasses + " classes (not looked"
                + " through)"), StaticState::state);
    }

    /** What {@code check} finds first in the class files of {@code locations}, or {@code tooMany}. */
    private static Optional<String> first(List<URL> locations, int maxClasses, Optional<String> tooMany,
                                          Function<byte[], Optional<String>> check) {
        int listed = 0;
        try {
            for (URL u : locations) {
                Path p = Path.of(u.toURI());
                if (Files.isDirectory(p)) {
                    List<Path> files;
                    try (Stream<Path> walk = Files.walk(p)) {
                        files = walk.filter(f -> isClassFile(f.getFileName().toString()) && Files.isRegularFile(f))
                                .toList();
                    }
                    listed += files.size();
                    if (listed > maxClasses) {
                        return tooMany;
                    }
                    for (Path f : files) {
                        Optional<String> found = check.apply(Files.readAllBytes(f));
                        if (found.isPresent()) {
                            return found;
                        }
                    }
                } else if (Files.isRegularFile(p)) {
                    try (JarFile jar = new JarFile(p.toFile())) {
                        // A jar's list of classes is read from its directory, without inflating any.
                        List<JarEntry> entries = jar.stream().filter(e -> isJarClass(e.getName())).toList();
                        listed += entries.size();
                        if (listed > maxClasses) {
                            return tooMany;
                        }
                        for (JarEntry e : entries) {
                            try (InputStream in = jar.getInputStream(e)) {
                                Optional<String> found = check.apply(in.readAllBytes());
                                if (found.isPresent()) {
                                    return found;
                                }
                            }
                        }
                    }
                }
            }
        } catch (IOException | URISyntaxException | RuntimeException e) {
            return Optional.of("a class path entry that could not be read (" + e + ")");
        }
        return Optional.empty();
    }

    /** {@link #of}, with a class file it cannot read counted as state. */
    private static Optional<String> state(byte[] classFile) {
        try {
            return of(classFile);
        } catch (IOException | RuntimeException e) {
            return Optional.of("a class file that could not be read (" + e + ")");
        }
    }

    /** A class in a jar: a multi-release jar's classes for later Java versions count, the rest of META-INF not. */
    private static boolean isJarClass(String name) {
        return isClassFile(name.substring(name.lastIndexOf('/') + 1))
                && (!name.startsWith("META-INF/") || name.startsWith("META-INF/versions/"));
    }

    private static boolean isClassFile(String fileName) {
        // module-info and package-info declare no fields.
        return fileName.endsWith(".class") && !fileName.contains("-");
    }

    /** The first field of this class file that can keep state, as "CLASS.FIELD", or empty. */
    static Optional<String> of(byte[] classFile) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(classFile));
        ConstantPool pool = ConstantPool.read(in);
        String[] utf8 = pool.utf8();
        int access = in.readUnsignedShort();
        String self = pool.className(in.readUnsignedShort());
        in.readUnsignedShort();
        in.skipNBytes(2L * in.readUnsignedShort());
        for (String u : utf8) {
            if ("getNewContinuityID".equals(u)) {
                // 0.60's counter of RsMotion, counted per class loader: shared classes would share it.
                return Optional.of("RsMotion's continuity counter (called by " + self.replace('/', '.') + ")");
            }
        }
        boolean isEnum = (access & ACC_ENUM) != 0;
        String selfType = "L" + self + ";";
        int fields = in.readUnsignedShort();
        for (int f = 0; f < fields; f++) {
            int flags = in.readUnsignedShort();
            String name = utf8[in.readUnsignedShort()];
            String type = utf8[in.readUnsignedShort()];
            int attributes = in.readUnsignedShort();
            for (int a = 0; a < attributes; a++) {
                in.readUnsignedShort();
                in.skipNBytes(in.readInt() & 0xFFFFFFFFL);
            }
            boolean isStatic = (flags & ACC_STATIC) != 0;
            boolean isFinal = (flags & ACC_FINAL) != 0;
            boolean keepsNoState;
            if (isStatic) {
                keepsNoState = isFinal && (isValue(type)
                        // An enum's constants and the array of them values() copies.
                        || (isEnum && (flags & ACC_ENUM) != 0 && type.equals(selfType))
                        || (isEnum && (flags & ACC_SYNTHETIC) != 0 && type.equals("[" + selfType))
                        // A switch on an enum: filled in once by the class's initializer.
                        || (name.startsWith("$SwitchMap$") && type.equals("[I")));
            } else {
                // An enum's constants are shared by whoever uses the class: their fields too.
                keepsNoState = !isEnum || (isFinal && isValue(type));
            }
            if (!keepsNoState) {
                return Optional.of(self.replace('/', '.') + "." + name);
            }
        }
        return Optional.empty();
    }

    /**
     * What a class file tells of the process's end: where its code calls {@code System.exit},
     * {@code Runtime.exit} or {@code Runtime.halt} ("CLASS.METHOD calls System.exit", a {@code main}
     * method left out), and the classes it refers to, as binary names.
     */
    record Calls(Optional<String> exit, Set<String> classes) {
    }

    /** "CLASS.METHOD calls System.exit" if this class file's code ends the process, else empty. */
    static Optional<String> exitCallIn(byte[] classFile) throws IOException {
        return calls(classFile).exit();
    }

    /** {@link Calls} of a class file. */
    static Calls calls(byte[] classFile) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(classFile));
        ConstantPool pool = ConstantPool.read(in);
        String[] utf8 = pool.utf8();
        int[] tags = pool.tags();
        int[] first = pool.first();
        int[] second = pool.second();
        int count = utf8.length;
        in.readUnsignedShort();
        String self = pool.className(in.readUnsignedShort());
        // What a run can reach from here: the class's supertypes, whose code it inherits, and what
        // the code of its methods other than main refers to.
        Set<String> classes = new LinkedHashSet<>();
        int superclass = in.readUnsignedShort();
        if (superclass != 0) {
            classes.add(binaryName(pool.className(superclass)));
        }
        int interfaces = in.readUnsignedShort();
        for (int i = 0; i < interfaces; i++) {
            classes.add(binaryName(pool.className(in.readUnsignedShort())));
        }
        // The entries that name a method ending the process.
        Map<Integer, String> exits = new HashMap<>();
        for (int i = 1; i < count; i++) {
            if (tags[i] == 10 || tags[i] == 11) {
                String owner = pool.className(first[i]);
                String name = utf8[first[second[i]]];
                if (("java/lang/System".equals(owner) && "exit".equals(name))
                        || ("java/lang/Runtime".equals(owner) && ("exit".equals(name) || "halt".equals(name)))) {
                    exits.put(i, owner.substring("java/lang/".length()) + "." + name);
                }
            }
        }
        skipMembers(in);
        int methods = in.readUnsignedShort();
        Optional<String> exit = Optional.empty();
        for (int m = 0; m < methods; m++) {
            in.readUnsignedShort();
            String name = utf8[in.readUnsignedShort()];
            String descriptor = utf8[in.readUnsignedShort()];
            // A main method is the robot's way to run on its own, over the network; a run never calls it.
            boolean main = name.equals("main") && descriptor.equals("([Ljava/lang/String;)V");
            int attributes = in.readUnsignedShort();
            for (int a = 0; a < attributes; a++) {
                String attribute = utf8[in.readUnsignedShort()];
                byte[] body = in.readNBytes(in.readInt());
                if (main || !attribute.equals("Code")) {
                    continue;
                }
                for (int index : referenced(body)) {
                    if (index < count && tags[index] == 7) {
                        classes.add(binaryName(pool.className(index)));
                    } else if (index < count && (tags[index] == 9 || tags[index] == 10 || tags[index] == 11)) {
                        classes.add(binaryName(pool.className(first[index])));
                    }
                    if (exit.isEmpty() && exits.containsKey(index)) {
                        exit = Optional.of(self.replace('/', '.') + "." + name + " calls " + exits.get(index));
                    }
                }
            }
        }
        return new Calls(exit, classes);
    }

    /** A class entry's name ({@code a/b/C}, or an array's descriptor) as a binary name. */
    private static String binaryName(String entry) {
        return entry.replaceFirst("^\\[+L?", "").replaceFirst(";$", "").replace('/', '.');
    }

    /**
     * The constant pool indexes that the code of a Code attribute refers to with the instructions that
     * name a class, a field or a method (ldc_w, get/put field and static, the invokes, new, anewarray,
     * checkcast, instanceof, multianewarray). The bytes are searched for those instructions rather than
     * decoded one after another: an operand that happens to read as one counts too, which at worst
     * makes a sweep look at a class more, or send its runs to processes of their own.
     */
    private static List<Integer> referenced(byte[] codeAttribute) {
        int length = ((codeAttribute[4] & 0xFF) << 24) | ((codeAttribute[5] & 0xFF) << 16)
                | ((codeAttribute[6] & 0xFF) << 8) | (codeAttribute[7] & 0xFF);
        List<Integer> found = new ArrayList<>();
        for (int i = 8; i + 2 < 8 + length && i + 2 < codeAttribute.length; i++) {
            int op = codeAttribute[i] & 0xFF;
            if (op == 0x13 || (op >= 0xB2 && op <= 0xB9) || op == 0xBB || op == 0xBD || op == 0xC0 || op == 0xC1
                    || op == 0xC5) {
                found.add(((codeAttribute[i + 1] & 0xFF) << 8) | (codeAttribute[i + 2] & 0xFF));
            }
        }
        return found;
    }

    /**
     * A class file's constant pool, read past its magic number and version: each entry's tag, the text
     * of its UTF-8 entries, and for a class entry its name's index, for a field, method or
     * name-and-type entry its two indexes.
     */
    private record ConstantPool(int[] tags, String[] utf8, int[] first, int[] second) {
        static ConstantPool read(DataInputStream in) throws IOException {
            if (in.readInt() != 0xCAFEBABE) {
                throw new IOException("not a class file");
            }
            in.readUnsignedShort();
            in.readUnsignedShort();
            int count = in.readUnsignedShort();
            ConstantPool pool = new ConstantPool(new int[count], new String[count], new int[count], new int[count]);
            for (int i = 1; i < count; i++) {
                int tag = in.readUnsignedByte();
                pool.tags[i] = tag;
                switch (tag) {
                    case 1 -> pool.utf8[i] = in.readUTF();
                    case 7 -> pool.first[i] = in.readUnsignedShort();
                    case 9, 10, 11, 12 -> {
                        pool.first[i] = in.readUnsignedShort();
                        pool.second[i] = in.readUnsignedShort();
                    }
                    case 8, 16, 19, 20 -> in.readUnsignedShort();
                    case 15 -> in.skipNBytes(3);
                    case 3, 4, 17, 18 -> in.skipNBytes(4);
                    case 5, 6 -> {
                        in.skipNBytes(8);
                        i++;
                    }
                    default -> throw new IOException("constant pool tag " + tag);
                }
            }
            return pool;
        }

        /** The name ({@code a/b/C}) of the class entry at {@code index}. */
        String className(int index) {
            return utf8[first[index]];
        }
    }

    /** Skips a class file's fields (or any list of members laid out as they are). */
    private static void skipMembers(DataInputStream in) throws IOException {
        int members = in.readUnsignedShort();
        for (int f = 0; f < members; f++) {
            in.skipNBytes(6);
            int attributes = in.readUnsignedShort();
            for (int a = 0; a < attributes; a++) {
                in.readUnsignedShort();
                in.skipNBytes(in.readInt() & 0xFFFFFFFFL);
            }
        }
    }


    /** A primitive or a string. */
    private static boolean isValue(String type) {
        return type.length() == 1 || type.equals("Ljava/lang/String;");
    }
}
