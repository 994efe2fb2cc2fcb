package rp1;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * {@code rp1 sweep ... --master URL} and {@code rp1 cluster}: the two commands that use Apache Spark,
 * run in a JVM of their own whose class path adds the Spark module's ({@code lib/spark/} of the
 * installed simulator), with the {@code --add-opens} options Spark needs on Java 17. Every other
 * command runs with no Spark class on its class path.
 */
final class SparkCommand {
    /** The main class of a sweep on Spark (module rp1-spark). */
    static final String SWEEP = "rp1.spark.SparkSweep";
    /** The main class of {@code rp1 cluster} (module rp1-spark). */
    static final String CLUSTER = "rp1.spark.Cluster";
    /** Where the Spark module is when it is not in {@code lib/spark/} beside the simulator's jar. */
    static final String LIB_PROPERTY = "rp1.spark.lib";
    /** How long the command waits for the sweep or cluster to stop after Ctrl-C. */
    private static final long STOP_SECONDS = 150;
    /** The packages Spark reaches into (as its launcher lists them for Java 17). */
    static final List<String> JVM_OPTIONS = jvmOptions();

    private SparkCommand() {
    }

    private static List<String> jvmOptions() {
        List<String> o = new ArrayList<>(List.of("-XX:+IgnoreUnrecognizedVMOptions"));
        for (String p : List.of("java.lang", "java.lang.invoke", "java.lang.reflect", "java.io", "java.net", "java.nio",
                "java.util", "java.util.concurrent", "java.util.concurrent.atomic", "jdk.internal.ref", "sun.nio.ch",
                "sun.nio.cs", "sun.security.action", "sun.util.calendar")) {
            o.add("--add-opens=java.base/" + p + "=ALL-UNNAMED");
        }
        o.add("--add-opens=java.security.jgss/sun.security.krb5=ALL-UNNAMED");
        o.add("-Djdk.reflect.useDirectMethodHandle=false");
        return List.copyOf(o);
    }

    /** Whether a sweep's arguments ask for Spark. */
    static boolean wanted(String[] sweepArgs) {
        return Arrays.asList(sweepArgs).contains("--master");
    }

    /**
     * The Spark module's folder: {@code -Drp1.spark.lib=DIR}, else {@code spark/} beside the jar
     * this class came from (the installed simulator's {@code lib/}); null if neither can be told.
     */
    static Path library() {
        String given = System.getProperty(LIB_PROPERTY);
        if (given != null) {
            return Paths.get(given);
        }
        try {
            Path here = Paths.get(SparkCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            return Files.isRegularFile(here) ? here.resolveSibling("spark") : null;
        } catch (URISyntaxException | SecurityException | NullPointerException e) {
            return null;
        }
    }

    /** {@code java [this JVM's options] [Spark's] -cp THIS:LIB/* MAIN ARGS}. */
    static List<String> command(String main, String[] args, Path library) {
        List<String> c = new ArrayList<>();
        c.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        c.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
        c.addAll(JVM_OPTIONS);
        c.addAll(List.of("-cp", System.getProperty("java.class.path") + File.pathSeparator + library.resolve("*"), main));
        c.addAll(Arrays.asList(args));
        return c;
    }

    /**
     * Runs {@code main} of the Spark module with {@code args} in a JVM of its own, sharing this one's
     * terminal, and returns its exit status. Ctrl-C reaches both: this one waits for the other to
     * stop its runs and then leaves with its status.
     */
    static int run(String main, String[] args, PrintStream err) {
        Path library = library();
        if (library == null || !Files.isDirectory(library)) {
            err.println("rp1: " + (main.equals(CLUSTER) ? "rp1 cluster" : "--master") + " needs the Spark module, which"
                    + " this installation does not have" + (library == null ? "" : " (no " + library + ")")
                    + ": build it with gradle installDist");
            return 1;
        }
        Process child;
        try {
            ProcessBuilder b = new ProcessBuilder(command(main, args, library)).inheritIO();
            // Spark takes the machine's address to bind to; for local[N], rp1 cluster and a cluster on
            // this machine that is 127.0.0.1.
            if (main.equals(CLUSTER) || Arrays.stream(args).anyMatch(a -> a.matches("local.*|spark://(127\\.0\\.0\\.1|localhost)[:/].*"))) {
                b.environment().putIfAbsent("SPARK_LOCAL_IP", "127.0.0.1");
            }
            child = b.start();
        } catch (IOException e) {
            err.println("rp1: cannot start Java: " + e.getMessage());
            return 1;
        }
        Thread waitForChild = new Thread(() -> {
            // SIGTERM to this process alone is passed on; Ctrl-C reached the child already.
            child.destroy();
            try {
                if (child.waitFor(STOP_SECONDS, TimeUnit.SECONDS)) {
                    Runtime.getRuntime().halt(child.exitValue());
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            child.destroyForcibly();
        }, "wait for the Spark command");
        Runtime.getRuntime().addShutdownHook(waitForChild);
        try {
            int status = child.waitFor();
            try {
                Runtime.getRuntime().removeShutdownHook(waitForChild);
            } catch (IllegalStateException e) {
                // Ctrl-C reached this process too and it is shutting down: the hook ends it with the
                // child's status.
            }
            return status;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }
}
