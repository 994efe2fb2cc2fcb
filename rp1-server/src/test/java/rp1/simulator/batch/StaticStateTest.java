package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Which classes can keep state in a static field, read from their class files: a sweep's runs share
 * a robot's classes only when none can, so a class that can and is passed over would leak one run's
 * state into the next.
 */
class StaticStateTest {
    static final class Constants {
        static final int LIMIT = 3;
        static final double SPEED = 0.5;
        static final String NAME = "robot";
        private int count;

        void tick() {
            count++;
        }
    }

    static final class Counter {
        static int runs;
    }

    static final class Course {
        static final double[] CORNERS = {1, 2};
    }

    static final class Dice {
        static final Random RANDOM = new Random(1);
    }

    enum Plain {
        AHEAD, TURNING
    }

    enum Measured {
        SHORT(0.1), LONG(1.0);

        private final double metres;

        Measured(double metres) {
            this.metres = metres;
        }

        double metres() {
            return metres;
        }
    }

    enum Tally {
        HITS;

        private int count;

        void add() {
            count++;
        }
    }

    enum WithBody {
        ONE {
            private int calls;

            @Override
            int call() {
                return ++calls;
            }
        };

        abstract int call();
    }

    static final class Switching {
        static int code(Plain p) {
            switch (p) {
                case AHEAD:
                    return 1;
                default:
                    return 2;
            }
        }
    }

    private static byte[] classFile(Class<?> type) throws IOException {
        String name = type.getName();
        try (InputStream in = type.getResourceAsStream(name.substring(name.lastIndexOf('.') + 1) + ".class")) {
            return in.readAllBytes();
        }
    }

    private static Optional<String> of(Class<?> type) throws IOException {
        return StaticState.of(classFile(type));
    }

    private static String name(Class<?> type, String field) {
        return type.getName() + "." + field;
    }

    @Test
    void finalPrimitivesAndStringsKeepNoStateWhateverTheInstancesDo() throws IOException {
        assertEquals(Optional.empty(), of(Constants.class));
        assertEquals(Optional.empty(), of(StaticStateTest.class), "no fields at all");
    }

    @Test
    void aStaticFieldThatCanChangeOrHoldsAnObjectKeepsState() throws IOException {
        assertEquals(Optional.of(name(Counter.class, "runs")), of(Counter.class));
        assertEquals(Optional.of(name(Course.class, "CORNERS")), of(Course.class), "an array's items can change");
        assertEquals(Optional.of(name(Dice.class, "RANDOM")), of(Dice.class), "a random source moves on");
    }

    /** No static field, but 0.60's continuity counter, which is its class loader's. */
    static final class Numbering {
        int next() {
            return rp1.rossum.RsMotion.getNewContinuityID();
        }
    }

    @Test
    void aClassThatCallsTheContinuityCounterKeepsStateThere() throws IOException {
        assertEquals(Optional.of("RsMotion's continuity counter (called by " + Numbering.class.getName() + ")"),
                of(Numbering.class));
    }

    /** A robot that gives up the whole process when its run goes wrong. */
    static final class Quitter {
        private int bumps;
        private final int id = 7;

        void bumped() {
            if (++bumps > 3) {
                Runtime.getRuntime().halt(id);
            }
        }
    }

    /** A robot that also runs on its own over the network: its main exits when it cannot connect. */
    static final class Standalone {
        private int steps;

        void step() {
            steps++;
        }

        public static void main(String[] args) {
            if (args.length > 1) {
                Launcher.go();
            }
            System.exit(args.length == 0 ? 1 : 0);
        }
    }

    /** What a robot's main may use to run on its own. */
    static final class Launcher {
        static void go() {
            System.exit(2);
        }
    }

    @Test
    void aClassWhoseCodeEndsTheProcessIsNamedButAMainMethodIsNoRunsCode() throws IOException {
        assertEquals(Optional.of(Quitter.class.getName() + ".bumped calls Runtime.halt"),
                StaticState.exitCallIn(classFile(Quitter.class)));
        assertEquals(Optional.empty(), StaticState.exitCallIn(classFile(Standalone.class)));
        assertTrue(!StaticState.calls(classFile(Standalone.class)).classes().contains(Launcher.class.getName()),
                "a class that only main uses is not reached by a run");
        assertEquals(Optional.of(Launcher.class.getName() + ".go calls System.exit"),
                StaticState.exitCallIn(classFile(Launcher.class)));
        assertEquals(Optional.empty(), StaticState.exitCallIn(classFile(Counter.class)));
    }

    @Test
    void enumsKeepStateOnlyInFieldsOfTheirConstantsThatCanChange() throws IOException {
        assertEquals(Optional.empty(), of(Plain.class));
        assertEquals(Optional.empty(), of(Measured.class));
        assertEquals(Optional.of(name(Tally.class, "count")), of(Tally.class));
        Class<?> body = WithBody.ONE.getClass();
        assertEquals(Optional.of(name(body, "calls")), of(body), "a constant's own class body");
        assertEquals(Optional.empty(), of(WithBody.class));
    }

    @Test
    void theCompilersTableForASwitchOnAnEnumKeepsNoState(@TempDir Path dir) throws Exception {
        assertEquals(2, Switching.code(Plain.TURNING));
        Path copy = copyNested(dir.resolve("classes"), List.of(Constants.class, Plain.class, Measured.class,
                Switching.class), true);
        assertEquals(Optional.empty(), StaticState.find(List.of(copy.toUri().toURL()), 100),
                "the classes with the switch's table, a folder");
    }

    @Test
    void aFolderOrJarWithOneClassThatKeepsStateIsNamedAndTooManyClassesAreNotLookedThrough(@TempDir Path dir)
            throws Exception {
        Path folder = copyNested(dir.resolve("folder"), List.of(Constants.class, Counter.class, Plain.class), false);
        URL folderUrl = folder.toUri().toURL();
        assertEquals(Optional.of(name(Counter.class, "runs")), StaticState.find(List.of(folderUrl), 100));
        Path jar = dir.resolve("robot.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            for (Class<?> c : List.of(Constants.class, Plain.class, Tally.class)) {
                out.putNextEntry(new JarEntry(c.getName().replace('.', '/') + ".class"));
                out.write(classFile(c));
                out.closeEntry();
            }
        }
        assertEquals(Optional.of(name(Tally.class, "count")), StaticState.find(List.of(jar.toUri().toURL()), 100));
        Path versioned = dir.resolve("versioned.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(versioned))) {
            out.putNextEntry(new JarEntry("META-INF/versions/17/" + Counter.class.getName().replace('.', '/') + ".class"));
            out.write(classFile(Counter.class));
            out.closeEntry();
        }
        assertEquals(Optional.of(name(Counter.class, "runs")), StaticState.find(List.of(versioned.toUri().toURL()), 100),
                "a multi-release jar's class for this Java");
        assertEquals(Optional.of("one of more than 2 classes (not looked through)"),
                StaticState.find(List.of(jar.toUri().toURL()), 2));
    }

    /**
     * Copies the class files of {@code types} into a package folder under {@code root}, with the
     * compiler's extra classes of this test (its switch table) if asked.
     */
    private static Path copyNested(Path root, List<Class<?>> types, boolean withSynthetic) throws Exception {
        Path pkg = root.resolve(StaticStateTest.class.getPackageName().replace('.', '/'));
        Files.createDirectories(pkg);
        for (Class<?> c : types) {
            String file = c.getName().substring(c.getName().lastIndexOf('.') + 1) + ".class";
            try (OutputStream out = Files.newOutputStream(pkg.resolve(file))) {
                out.write(classFile(c));
            }
        }
        if (withSynthetic) {
            // The compiler's numbered classes of this test: the one with the switch's table.
            Path compiled = Path.of(StaticStateTest.class.getResource("StaticStateTest.class").toURI()).getParent();
            int tables = 0;
            try (var files = Files.list(compiled)) {
                for (Path f : (Iterable<Path>) files::iterator) {
                    String n = f.getFileName().toString();
                    if (n.matches("StaticStateTest\\$\\d+\\.class")) {
                        byte[] bytes = Files.readAllBytes(f);
                        tables += new String(bytes, StandardCharsets.ISO_8859_1).contains("$SwitchMap$") ? 1 : 0;
                        Files.write(pkg.resolve(n), bytes);
                    }
                }
            }
            assertEquals(1, tables, "the switch's table is among the classes");
        }
        return root;
    }
}
