package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsClient;

/** Each run's loader gives the robot classes of its own, from what the sweep worked out once. */
class RunClassLoaderTest {
    private static final String ROBOT = ExperimentDlc.class.getName();

    @Test
    void everyRunLoadsTheRobotAfreshAndSharesTheLibrary() throws Exception {
        ClassLoader sweep = RunClassLoaderTest.class.getClassLoader();
        RunClassLoader.Source source = RunClassLoader.source(List.of(ROBOT), sweep);
        try (RunClassLoader first = source.newLoader(); RunClassLoader second = source.newLoader()) {
            Class<?> a = first.loadClass(ROBOT);
            Class<?> b = second.loadClass(ROBOT);
            assertNotSame(a, b, "each run has a robot class of its own");
            assertNotSame(ExperimentDlc.class, a, "and not the sweep's");
            assertSame(first, a.getClassLoader());
            // The library, asked through the robot's class and through the loader, is the sweep's in both runs.
            assertSame(RsClient.class, a.getSuperclass());
            assertSame(RsClient.class, b.getSuperclass());
            assertSame(RsClient.class, second.loadClass(RsClient.class.getName()));
            assertSame(String.class, first.loadClass("java.lang.String"));
        }
    }

    @Test
    void theSharingDecisionIsTheSameForEveryRun() throws Exception {
        RunClassLoader.Source source = RunClassLoader.source(List.of(ROBOT), RunClassLoaderTest.class.getClassLoader());
        assertEquals(true, source.isShared(RsClient.class.getName()));
        assertEquals(false, source.isShared(ROBOT));
        assertEquals(false, source.isShared("no.such.Robot"), "what no one has is looked for in the run's own path");
        assertEquals(true, source.isShared(RsClient.class.getName()), "asked again");
        assertEquals(false, source.isShared(ROBOT), "asked again");
    }

    /**
     * Runs side by side read the robot's rossum.ini from its jar while others end and close their
     * loaders. Each run must read the whole file: before, a loader's close pulled the jar that all of
     * them shared from under the others (nearly every read failed in this test, about one run in
     * 4,000 in a sweep of bumper runs).
     */
    @Test
    void runsEndingDoNotCloseTheJarOtherRunsAreReading(@TempDir Path dir) throws Exception {
        String settings = "logToSystemOut=false\n# " + "x".repeat(4000) + "\n";
        Path jar = robotJar(dir, settings);
        try (URLClassLoader sweep = new URLClassLoader(new URL[] {jar.toUri().toURL()},
                RunClassLoaderTest.class.getClassLoader())) {
            RunClassLoader.Source source = RunClassLoader.source(List.of("probe.Probe"), sweep);
            ExecutorService jobs = Executors.newFixedThreadPool(4);
            try {
                List<Future<Integer>> runs = new ArrayList<>();
                for (int job = 0; job < 4; job++) {
                    runs.add(jobs.submit(() -> {
                        int read = 0;
                        for (int run = 0; run < 300; run++) {
                            try (RunClassLoader loader = source.newLoader()) {
                                Class<?> robot = loader.loadClass("probe.Probe");
                                assertSame(loader, robot.getClassLoader());
                                try (InputStream in = robot.getResourceAsStream("rossum.ini")) {
                                    assertEquals(settings, new String(in.readAllBytes(), StandardCharsets.UTF_8));
                                    read++;
                                }
                            }
                        }
                        return read;
                    }));
                }
                for (Future<Integer> run : runs) {
                    assertEquals(300, run.get(), "every run read its settings");
                }
            } finally {
                jobs.shutdownNow();
            }
        }
    }

    @Test
    void aRobotsClassesAreDefinedAsFromItsJarAndItsFolderResourcesRead(@TempDir Path dir) throws Exception {
        Path jar = robotJar(dir, "logToSystemOut=false\n");
        try (URLClassLoader sweep = new URLClassLoader(new URL[] {jar.toUri().toURL()},
                RunClassLoaderTest.class.getClassLoader())) {
            RunClassLoader.Source source = RunClassLoader.source(List.of("probe.Probe"), sweep);
            try (RunClassLoader first = source.newLoader(); RunClassLoader second = source.newLoader()) {
                Class<?> a = first.loadClass("probe.Probe");
                Class<?> b = second.loadClass("probe.Probe");
                assertNotSame(a, b, "each run defines the robot anew from what the sweep read once");
                assertEquals(jar.toUri().toURL(), a.getProtectionDomain().getCodeSource().getLocation());
                assertEquals("probe", a.getPackage().getName());
                assertEquals("1.2", a.getPackage().getImplementationVersion(), "the jar's manifest");
                assertEquals(new URL("jar:" + jar.toUri().toURL() + "!/probe/rossum.ini"), a.getResource("rossum.ini"));
                assertEquals(null, a.getResource("missing.ini"));
                assertThrows(ClassNotFoundException.class, () -> first.loadClass("probe.Missing"));
            }
        }
        // A robot in a folder of classes (as an IDE builds it), its settings beside its class.
        Path classes = dir.resolve("classes");
        Files.writeString(classes.resolve("probe/rossum.ini"), "logToSystemOut=true\n");
        try (URLClassLoader sweep = new URLClassLoader(new URL[] {classes.toUri().toURL()},
                RunClassLoaderTest.class.getClassLoader())) {
            RunClassLoader.Source source = RunClassLoader.source(List.of("probe.Probe"), sweep);
            try (RunClassLoader loader = source.newLoader()) {
                Class<?> robot = loader.loadClass("probe.Probe");
                assertEquals(classes.toUri().toURL(), robot.getProtectionDomain().getCodeSource().getLocation());
                try (InputStream in = robot.getResourceAsStream("rossum.ini")) {
                    assertEquals("logToSystemOut=true\n", new String(in.readAllBytes(), StandardCharsets.UTF_8));
                }
            }
        }
    }

    /** A jar with a robot class {@code probe.Probe} and its {@code rossum.ini}, as a robot of one's own ships. */
    private static Path robotJar(Path dir, String settings) throws IOException {
        Path src = Files.createDirectories(dir.resolve("src/probe"));
        Files.writeString(src.resolve("Probe.java"), "package probe;\npublic class Probe {\n}\n");
        Path classes = Files.createDirectories(dir.resolve("classes"));
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertEquals(0, javac.run(null, null, null, "-d", classes.toString(), src.resolve("Probe.java").toString()));
        Path jar = dir.resolve("probe.jar");
        Manifest manifest = new Manifest();
        manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        manifest.getMainAttributes().put(Attributes.Name.IMPLEMENTATION_VERSION, "1.2");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest)) {
            out.putNextEntry(new JarEntry("probe/Probe.class"));
            out.write(Files.readAllBytes(classes.resolve("probe/Probe.class")));
            out.closeEntry();
            out.putNextEntry(new JarEntry("probe/rossum.ini"));
            out.write(settings.getBytes(StandardCharsets.UTF_8));
            out.closeEntry();
        }
        return jar;
    }
}
