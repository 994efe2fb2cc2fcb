package rp1.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.apache.spark.launcher.JavaModuleOptions;

/**
 * A standalone Spark cluster on 127.0.0.1 to try a sweep on: {@code rp1 cluster --workers N} starts
 * a master and N workers, each a JVM of its own run from this process's class path (Spark's own
 * {@code Master} and {@code Worker}, no Spark download), prints the master's URL, and stops them all
 * on Ctrl-C. Their logs are in the cluster's folder (a temporary one unless {@code --dir}).
 */
public final class Cluster implements AutoCloseable {
    static final String USAGE = String.join("\n",
            "usage: rp1 cluster [--workers N] [--cores C] [--memory M] [--dir DIR]",
            "  A standalone Spark master and N workers (default 2) on 127.0.0.1, for rp1 sweep --master URL;",
            "  each worker offers C cores (default 1) and M of memory (default 1g). Ctrl-C stops them all.");
    /** How long a master or worker may take to start. */
    private static final long START_SECONDS = 90;
    private static final Pattern MASTER_URL = Pattern.compile("Starting Spark master at (spark://\\S+)");
    private static final String REGISTERED = "Successfully registered with master";
    /** The daemons' own messages: what the cluster waits for, and warnings. */
    private static final String LOG_CONFIG = String.join("\n",
            "rootLogger.level = warn",
            "rootLogger.appenderRef.stderr.ref = console",
            "appender.console.type = Console",
            "appender.console.name = console",
            "appender.console.target = SYSTEM_ERR",
            "appender.console.layout.type = PatternLayout",
            "appender.console.layout.pattern = %d{HH:mm:ss} %p %c{1}: %m%n%ex",
            "logger.master.name = org.apache.spark.deploy.master.Master",
            "logger.master.level = info",
            "logger.worker.name = org.apache.spark.deploy.worker.Worker",
            "logger.worker.level = info", "");

    private final Path dir;
    private final Process master;
    private final String masterUrl;
    private final List<Process> workers = new ArrayList<>();
    /** A JVM's exit status when Ctrl-C (SIGINT) ended it, as a shell reports it. */
    private static final int STOPPED_BY_CTRL_C = 130;
    /** A JVM's exit status when SIGTERM ended it. */
    private static final int STOPPED_BY_SIGTERM = 143;
    /** Stops the daemons if this JVM ends without closing the cluster: they never outlive it. */
    private final Thread stopOnExit = new Thread(this::stopAll, "stop the cluster");

    private Cluster(Path dir, Process master, String masterUrl) {
        this.dir = dir;
        this.master = master;
        this.masterUrl = masterUrl;
        Runtime.getRuntime().addShutdownHook(stopOnExit);
    }

    /**
     * Starts a master and {@code workers} workers, and returns once every worker has registered.
     *
     * @param dir the cluster's folder: logs, the workers' folders
     * @throws IOException if one of them did not start (the message quotes its log)
     */
    public static Cluster start(int workers, int cores, String memory, Path dir) throws IOException, InterruptedException {
        Files.createDirectories(dir.resolve("home/jars"));
        Files.write(dir.resolve("log4j2.properties"), LOG_CONFIG.getBytes(StandardCharsets.UTF_8));
        Path masterLog = dir.resolve("master.log");
        Process master = daemon(dir, masterLog, "org.apache.spark.deploy.master.Master",
                "--host", "127.0.0.1", "--port", "0", "--webui-port", "0");
        Cluster cluster;
        try {
            Matcher m = await(master, masterLog, MASTER_URL, "the master");
            cluster = new Cluster(dir, master, m.group(1));
        } catch (IOException | InterruptedException e) {
            destroy(master);
            throw e;
        }
        try {
            for (int i = 1; i <= workers; i++) {
                Path log = dir.resolve("worker-" + i + ".log");
                Files.createDirectories(dir.resolve("worker-" + i));
                Process w = daemon(dir, log, "org.apache.spark.deploy.worker.Worker", "--host", "127.0.0.1",
                        "--cores", Integer.toString(cores), "--memory", memory, "--webui-port", "0",
                        "--work-dir", dir.resolve("worker-" + i).toString(), cluster.masterUrl);
                cluster.workers.add(w);
            }
            for (int i = 0; i < workers; i++) {
                await(cluster.workers.get(i), dir.resolve("worker-" + (i + 1) + ".log"), Pattern.compile(REGISTERED),
                        "worker " + (i + 1));
            }
        } catch (IOException | InterruptedException e) {
            cluster.close();
            throw e;
        }
        return cluster;
    }

    /** {@code java [Spark's --add-opens] -cp THIS-CLASS-PATH MAIN ARGS}, its output into {@code log}. */
    private static Process daemon(Path dir, Path log, String main, String... args) throws IOException {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(Arrays.asList(JavaModuleOptions.defaultModuleOptions().split(" ")));
        command.addAll(List.of("-Xmx256m", "-Djava.awt.headless=true",
                "-Dlog4j2.configurationFile=" + dir.resolve("log4j2.properties").toUri(),
                "-cp", System.getProperty("java.class.path"), main));
        command.addAll(Arrays.asList(args));
        ProcessBuilder b = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile());
        Map<String, String> env = b.environment();
        // The worker builds its executors' command line with Spark's launcher, which wants a Spark
        // home with a jars/ folder; the executors' class path comes from the driver instead.
        env.put("SPARK_HOME", dir.resolve("home").toString());
        env.put("SPARK_SCALA_VERSION", "2.13");
        env.put("SPARK_LOCAL_IP", "127.0.0.1");
        env.put("SPARK_LOCAL_DIRS", dir.resolve("local").toString());
        return b.start();
    }

    /** Waits for {@code pattern} in the log of {@code p}. */
    private static Matcher await(Process p, Path log, Pattern pattern, String what) throws IOException, InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(START_SECONDS);
        while (System.nanoTime() < end) {
            String text = Files.exists(log) ? Files.readString(log) : "";
            Matcher m = pattern.matcher(text);
            if (m.find()) {
                return m;
            }
            if (!p.isAlive()) {
                throw new IOException(what + " stopped (status " + p.exitValue() + "): " + tail(text));
            }
            Thread.sleep(100);
        }
        throw new IOException(what + " did not start within " + START_SECONDS + " s: see " + log);
    }

    private static String tail(String text) {
        List<String> lines = text.lines().filter(l -> !l.isBlank()).toList();
        return lines.isEmpty() ? "it printed nothing" : String.join("\n", lines.subList(Math.max(0, lines.size() - 5), lines.size()));
    }

    /** The master's URL, for {@code --master}. */
    public String masterUrl() {
        return masterUrl;
    }

    /** The cluster's folder. */
    public Path dir() {
        return dir;
    }

    /**
     * Kills worker {@code i} (from 1) and its executors at once, as a machine that dies: the worker
     * first, so that it cannot tell the master its executors died and be given new ones (failures the
     * master counts against the application), then the executors it leaves.
     */
    public void killWorker(int i) throws InterruptedException {
        Process w = workers.get(i - 1);
        List<ProcessHandle> executors = w.descendants().toList();
        w.destroyForcibly();
        w.waitFor();
        executors.forEach(ProcessHandle::destroyForcibly);
    }

    /** Stops the workers (and their executors), then the master. */
    @Override
    public void close() {
        try {
            Runtime.getRuntime().removeShutdownHook(stopOnExit);
        } catch (IllegalStateException e) {
            // The JVM is ending: the hook stops them.
            return;
        }
        stopAll();
    }

    private void stopAll() {
        workers.forEach(Cluster::destroy);
        destroy(master);
    }

    private static void destroy(Process p) {
        p.descendants().forEach(ProcessHandle::destroy);
        p.destroy();
        try {
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }

    /** {@code rp1 cluster}: starts the cluster, prints its URL, and stops it on Ctrl-C. */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    static int run(String[] args, PrintStream out, PrintStream err) {
        int workers = 2;
        int cores = 1;
        String memory = "1g";
        Path dir = null;
        try {
            for (int i = 0; i < args.length; i++) {
                switch (args[i]) {
                    case "-h", "--help" -> {
                        out.println(USAGE);
                        return 0;
                    }
                    case "--workers" -> workers = count(args, ++i);
                    case "--cores" -> cores = count(args, ++i);
                    case "--memory" -> memory = value(args, ++i);
                    case "--dir" -> dir = Paths.get(value(args, ++i)).toAbsolutePath();
                    default -> throw new IllegalArgumentException("unknown option " + args[i]);
                }
            }
        } catch (IllegalArgumentException e) {
            err.println("rp1 cluster: " + e.getMessage() + "\n" + USAGE);
            return 1;
        }
        try {
            Path folder = dir != null ? dir : Files.createTempDirectory("rp1-cluster-");
            Cluster cluster = start(workers, cores, memory, folder);
            out.println("rp1 cluster: master " + cluster.masterUrl() + ", " + workers + " worker" + (workers == 1 ? "" : "s")
                    + " of " + cores + " core" + (cores == 1 ? "" : "s") + " and " + memory + "; logs in " + folder
                    + ". Ctrl-C stops them.\n  rp1 sweep ... --master " + cluster.masterUrl());
            int status = master(cluster).waitFor();
            if (status == STOPPED_BY_CTRL_C || status == STOPPED_BY_SIGTERM) {
                // Ctrl-C reaches the whole process group, the master first as often as not: the cluster
                // was asked to stop, and the hook stops what is left of it.
                out.println("rp1 cluster: stopped");
                return 0;
            }
            err.println("rp1 cluster: the master stopped by itself (status " + status + "); see "
                    + folder.resolve("master.log"));
            return 1;
        } catch (IOException e) {
            err.println("rp1 cluster: " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            return 130;
        }
    }

    private static Process master(Cluster c) {
        return c.master;
    }

    private static String value(String[] args, int i) {
        if (i >= args.length) {
            throw new IllegalArgumentException(args[i - 1] + " needs a value");
        }
        return args[i];
    }

    private static int count(String[] args, int i) {
        String v = value(args, i);
        try {
            int n = Integer.parseInt(v);
            if (n >= 1 && n <= 64) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException(args[i - 1] + " needs a whole number from 1 to 64, got " + v);
    }
}
