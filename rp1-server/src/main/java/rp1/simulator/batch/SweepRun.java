package rp1.simulator.batch;

import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import rp1.simulator.Simulation;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;
import rp1.simulator.launch.StartupException;
import rp1.simulator.launch.ViewHook;

/**
 * One run of a sweep, in a process of its own: {@code java rp1.simulator.batch.SweepRun DIR [-cp PATH]}
 * starts the server with {@code DIR/run.ini} (and the robot's class path) (which the sweep wrote: the user's properties with the run's
 * seed, plan and output files), waits until it stops, and leaves {@link RunReport#FILE} and
 * {@link TrailFile#FILE} in DIR. The process's exit status is the server's.
 */
public final class SweepRun {
    /** The properties a sweep writes into each run's folder. */
    public static final String PROPERTIES = "run.ini";
    /** The server's log in each run's folder. */
    public static final String LOG = "server.log";
    /** How long stopping waits for a server that is starting. */
    private static final long START_WAIT_SECONDS = 30;

    private final Path dir;
    /** The server's arguments beyond -p: the robot's class path, if any. */
    private final List<String> serverArguments;
    private RunStatistics statistics;
    private List<RobotResult> robots = List.of();
    private double endTime = Double.NaN;

    private SweepRun(Path dir, List<String> serverArguments) {
        this.dir = dir;
        this.serverArguments = serverArguments;
    }

    /** Runs the run in the folder given; the process exits with the server's status. */
    public static void main(String[] args) {
        if (args.length != 1 && !(args.length == 3 && args[1].equals("-cp"))) {
            System.err.println("usage: java rp1.simulator.batch.SweepRun RUN-FOLDER [-cp PATH] (started by rp1.Sweep)");
            System.exit(ExitStatus.STARTUP_FAILED);
        }
        List<String> rest = Arrays.asList(args).subList(1, args.length);
        System.exit(new SweepRun(Paths.get(args[0]).toAbsolutePath(), rest).run());
    }

    private int run() {
        // Stopped by the sweep (a timeout, the sweep interrupted: SIGTERM), even while it starts, the
        // run still closes its recording and event log before the process ends.
        CompletableFuture<RunningServer> started = new CompletableFuture<>();
        Runtime.getRuntime().addShutdownHook(new Thread(() -> stopOnceStarted(started), "stop the run"));
        RunningServer server = null;
        try {
            List<String> args = new ArrayList<>(List.of("-p", dir.resolve(PROPERTIES).toString()));
            args.addAll(serverArguments);
            server = ServerLauncher.start(args.toArray(new String[0]),
                    Paths.get("").toAbsolutePath(), LaunchOptions.defaults().withPort(0).withView(this::watch));
        } catch (StartupException e) {
            return report(RunReport.failed("startup failed: " + e.getMessage(), e.getExitStatus()));
        } finally {
            started.complete(server);
        }
        int status;
        try {
            status = server.awaitExit();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return ExitStatus.OK;
        }
        return report(new RunReport(endTime, server.getStopReason(), status, robots));
    }

    /** The shutdown hook: waits until the server has started (if it is starting), then stops it cleanly. */
    private static void stopOnceStarted(CompletableFuture<RunningServer> started) {
        try {
            RunningServer server = started.get(START_WAIT_SECONDS, TimeUnit.SECONDS);
            if (server != null) {
                server.stop();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException e) {
            // It did not start: there is nothing to close.
        }
    }

    /**
     * The server's view: the standard one (which writes the picture at the end), with the statistics
     * watching beside it; when the server stops, the results are taken before the clients are closed.
     */
    private AutoCloseable watch(ViewHook.Context context) throws Exception {
        Simulation simulation = context.simulation;
        statistics = RunStatistics.watch(simulation);
        AutoCloseable view = ViewHook.standard().open(context);
        return () -> {
            endTime = simulation.getScheduler().recordedTime();
            robots = statistics.results(simulation.getWorld());
            view.close();
        };
    }

    private int report(RunReport report) {
        try {
            report.write(dir);
            if (statistics != null) {
                TrailFile.write(dir, statistics.trails());
            }
        } catch (IOException e) {
            System.err.println("rp1.simulator.batch.SweepRun: cannot write the run's results in " + dir + ": "
                    + e.getMessage());
        }
        return report.exitStatus();
    }
}
