package rp1.spark;

import java.io.PrintStream;
import java.net.InetAddress;
import java.net.URI;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;

import rp1.Sweep;
import rp1.simulator.batch.Interruption;
import rp1.simulator.batch.SweepOptions;

/**
 * {@code rp1 sweep ... --master URL [--keep NAMES]}: the sweep of {@link Sweep}, its runs carried out
 * as Spark tasks ({@link SparkRuns}) by {@code local[N]} (threads of this process), a standalone
 * cluster ({@code spark://HOST:PORT}) or, through {@code spark-submit}, YARN or Kubernetes. The
 * results, the pictures and the run folders are written on this machine, in {@code --out}, as the
 * sweep writes them on its own.
 */
public final class SparkSweep {
    /** What this command adds to {@code rp1 sweep}'s. */
    public static final String USAGE = String.join("\n",
            "  --master URL   carry the runs out on Apache Spark: local[N] (N threads of this process),",
            "                 spark://HOST:PORT (a standalone cluster; rp1 cluster starts one), or yarn, k8s://...",
            "                 through spark-submit; --jobs then says how many runs are submitted at once",
            "                 (default: the executors' cores when the sweep starts)",
            "  --keep NAMES   files of each run (recording.txt, events.txt, end.png, ... or all) to bring back",
            "                 from the executors whatever their size; others larger than 4 MB stay there");
    /**
     * The forms of master URL Spark takes: refused here rather than by Spark, whose refusal comes as an
     * error logged with its stack trace before the sweep can say a word.
     */
    private static final String MASTER_URL = "local(\\[(\\d+|\\*)(,\\d+)?\\])?|local-cluster\\[.+\\]|(spark|k8s|mesos)://.+|yarn";
    /** The command users start a sweep with. */
    private static final String COMMAND = "rp1 sweep";
    /** How long the sweep waits for the first executor of a cluster. */
    private static final long EXECUTOR_WAIT_SECONDS = 120;

    private SparkSweep() {
    }

    /** Runs the sweep; the process exits with its status. */
    public static void main(String[] args) {
        Interruption.runAndExit(COMMAND, i -> run(args, System.out, System.err, System.console() != null, i));
    }

    /**
     * Runs the sweep the command line asks for on the Spark master it names.
     *
     * @return the exit status, as {@link Sweep#run} says
     */
    public static int run(String[] args, PrintStream out, PrintStream err, boolean terminal, Interruption interruption) {
        List<String> rest = new ArrayList<>();
        String master = null;
        Set<String> keep = new LinkedHashSet<>();
        boolean jobsGiven = false;
        for (int i = 0; i < args.length; i++) {
            if ((args[i].equals("--master") || args[i].equals("--keep")) && i + 1 >= args.length) {
                err.println("rp1.Sweep: " + args[i] + " needs a value");
                return 1;
            }
            switch (args[i]) {
                case "--master" -> master = args[++i];
                case "--keep" -> keep.addAll(Arrays.asList(args[++i].split(",")));
                default -> {
                    jobsGiven |= args[i].equals("--jobs");
                    rest.add(args[i]);
                }
            }
        }
        // The user's own words, for the advice on going on after an interruption (not the --jobs added below).
        Sweep.Invocation how = new Sweep.Invocation(COMMAND, List.of(args));
        if (master == null && !keep.isEmpty()) {
            err.println("rp1.Sweep: --keep says which files to bring back from a cluster's executors: it needs --master");
            return 1;
        }
        if (master == null) {
            return Sweep.run(how, rest.toArray(new String[0]), out, err, terminal, interruption, null);
        }
        if (rest.contains("-h") || rest.contains("--help")) {
            out.println(Sweep.usage(COMMAND, "--master URL [--keep NAMES]", USAGE.split("\n")));
            return 0;
        }
        if (!master.matches(MASTER_URL)) {
            err.println("rp1.Sweep: --master " + master + ": not a master URL Spark knows (local, local[N], local[*],"
                    + " spark://HOST:PORT, yarn, k8s://...)");
            return 1;
        }
        JavaSparkContext spark;
        try {
            spark = new JavaSparkContext(conf(master));
        } catch (Exception e) {
            // Spark's own exceptions (a master URL it cannot parse) are checked ones Java is not told of.
            err.println("rp1.Sweep: --master " + master + ": Spark did not start: " + e.getMessage());
            return 1;
        }
        try {
            if (!jobsGiven) {
                String missing = waitForExecutors(spark, master, out);
                if (missing != null) {
                    err.println("rp1.Sweep: --master " + master + ": " + missing);
                    return 1;
                }
                rest.add("--jobs");
                rest.add(Integer.toString(Math.min(1000, spark.defaultParallelism())));
            }
            return Sweep.run(how, rest.toArray(new String[0]), out, err, terminal, interruption,
                    batch -> SparkRuns.open(spark, batch, keep, batch.options().isolation == SweepOptions.Isolation.PROCESS
                            ? new ProcessRun() : new IsolatedRun(), Paths.get("").toAbsolutePath()));
        } finally {
            spark.stop();
        }
    }

    /**
     * The context's settings: the master, and, unless set already ({@code -Dspark.KEY=VALUE}), no web
     * page, 512 MB executors with the quick compiler only, the executors' class path the driver's (an rp1 installed at the same
     * place on every machine), and on a loopback master, a driver on the loopback address.
     */
    static SparkConf conf(String master) {
        SparkConf conf = new SparkConf().setMaster(master).setAppName("rp1 sweep")
                .setIfMissing("spark.ui.enabled", "false")
                .setIfMissing("spark.executor.memory", "512m")
                // As ./rp1 sweep runs: each run's robot classes are new classes, compiled anew, and a
                // run computes for milliseconds, which the optimizing compiler's work never pays back.
                .setIfMissing("spark.executor.extraJavaOptions", "-XX:TieredStopAtLevel=1")
                .setIfMissing("spark.executor.extraClassPath", System.getProperty("java.class.path"));
        if (master.startsWith("local") || loopback(master)) {
            conf.setIfMissing("spark.driver.host", "127.0.0.1").setIfMissing("spark.driver.bindAddress", "127.0.0.1");
        }
        return conf;
    }

    private static boolean loopback(String master) {
        try {
            String host = URI.create(master).getHost();
            return host != null && InetAddress.getByName(host).isLoopbackAddress();
        } catch (Exception e) {
            return false;
        }
    }

    /**
     * On a cluster, until the executors have come (without them, their cores are not known): until
     * one has, and then no other for a second. Null then; else why none came.
     */
    private static String waitForExecutors(JavaSparkContext spark, String master, PrintStream out) {
        if (master.startsWith("local")) {
            return null;
        }
        out.println("rp1.Sweep: waiting for the executors of " + master);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(EXECUTOR_WAIT_SECONDS);
        long quiet = 0;
        int seen = 0;
        while (System.nanoTime() < end) {
            if (spark.sc().isStopped()) {
                // Spark gives up on a master that does not answer (after a minute) and stops the context.
                return "the master did not answer, and Spark gave up on it (is it running, and is this its address?"
                        + " rp1 cluster starts one)";
            }
            // The driver is one of the "executors" the tracker lists.
            int now = spark.sc().statusTracker().getExecutorInfos().length - 1;
            if (now > 0 && now == seen && ++quiet >= 10) {
                return null;
            }
            if (now != seen) {
                quiet = 0;
                seen = now;
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return "interrupted while waiting for the executors";
            }
        }
        return seen > 0 ? null : "no executor joined within " + EXECUTOR_WAIT_SECONDS + " s (has the cluster any workers?"
                + " rp1 cluster --workers N starts them)";
    }
}
