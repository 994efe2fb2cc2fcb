package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;

import rp1.io.IoFailures;
import rp1.planparser.ParsedPlans;
import rp1.simulator.Simulation;
import rp1.simulator.config.ServerArguments;
import rp1.simulator.launch.ClientClassPath;
import rp1.simulator.launch.ExitCaller;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.HelperThreads;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.launch.ServerLauncher;
import rp1.simulator.launch.StartupException;
import rp1.simulator.launch.ViewHook;
import rp1.simulator.outcome.RobotResult;
import rp1.simulator.outcome.RunStatistics;
import rp1.simulator.outcome.Trail;

/**
 * One run of a sweep: starts the server with {@code DIR/run.ini} (which the sweep wrote: the user's
 * properties with the run's configuration, seed, plan and output files), with the robot's classes
 * from the class loader given, and, if the sweep has a {@code --client}, the client's program
 * ({@link ExternalClient}); waits until it stops, and leaves {@link RunReport#FILE} and
 * {@link TrailFile#FILE} in DIR. The sweep runs it in its own process ({@code --isolation loader}) or
 * as {@code java rp1.simulator.batch.SweepRun DIR [-cp PATH]} ({@code --isolation process}; {@code -cp}
 * names the robot's classes, as {@code rp1 sweep -cp} did), whose exit status is the server's.
 */
public final class SweepRun {
    /** The properties a sweep writes into each run's folder. */
    public static final String PROPERTIES = "run.ini";
    /** The server's log in each run's folder. */
    public static final String LOG = "server.log";
    /** The {@code --client} command, in the run's folder when the sweep has one. */
    static final String CLIENT_COMMAND = "client-command.txt";
    /** How often a run with a {@code --client} looks whether the client's program is still going. */
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(50);
    /** How long stopping waits for a server that is starting. */
    private static final long START_WAIT_SECONDS = 30;

    private final Path dir;
    private final ClassLoader loader;
    /** The plans parsed once for the sweep's runs in this process; null: the run parses its own. */
    private final ParsedPlans plans;
    /** Where the server starts its client starter and its stop. */
    private final HelperThreads helpers;
    private RunStatistics statistics;
    /** The robots' trails as the report left them in the folder: worked out once, for the file and the sweep. */
    private List<Trail> trails = List.of();
    private List<RobotResult> robots = List.of();
    private double endTime = Double.NaN;

    SweepRun(Path dir, ClassLoader loader, ParsedPlans plans, HelperThreads helpers) {
        this.dir = dir;
        this.loader = loader;
        this.plans = plans;
        this.helpers = helpers;
    }

    /** Runs the run in the folder given; the process exits with the server's status. */
    public static void main(String[] args) {
        if (args.length != 1 && !(args.length == 3 && args[1].equals("-cp"))) {
            System.err.println("usage: java rp1.simulator.batch.SweepRun RUN-FOLDER [-cp PATH] (started by rp1.Sweep)");
            System.exit(ExitStatus.STARTUP_FAILED);
        }
        // Stopped by the sweep (a timeout, the sweep interrupted: SIGTERM), even while it starts, the
        // run still closes its recording and event log before the process ends.
        CompletableFuture<RunningServer> started = new CompletableFuture<>();
        CountDownLatch reported = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> stopOnceStarted(started, reported), "stop the run"));
        // A sweep killed outright (SIGKILL) stops nothing: a run whose sweep is gone stops itself, as
        // stopped, rather than run on for ever re-parented to init.
        ProcessHandle.current().parent().ifPresent(sweep -> sweep.onExit().thenRun(() -> System.exit(Interruption.STATUS)));
        ClassLoader robots = SweepRun.class.getClassLoader();
        if (args.length == 3) {
            try {
                robots = ClientClassPath.loader(ClientClassPath.resolve(
                        ServerArguments.entries(args[2]), Paths.get("").toAbsolutePath()), robots);
            } catch (StartupException e) {
                System.err.println("rp1.simulator.batch.SweepRun: -cp: " + e.getMessage());
                System.exit(ExitStatus.STARTUP_FAILED);
            }
        }
        SweepRun run = new SweepRun(Paths.get(args[0]).toAbsolutePath(), robots, null, HelperThreads.newThreads());
        RunReport report;
        try {
            report = run.run(started::complete, Double.POSITIVE_INFINITY);
        } catch (InterruptedException e) {
            report = RunReport.failed("interrupted", Interruption.STATUS);
        } finally {
            started.complete(null);
        }
        reported.countDown();
        System.exit(report.exitStatus());
    }

    /**
     * Runs the run here and leaves its report and trails in its folder.
     *
     * @param started        told the server once it has started (to stop it from elsewhere)
     * @param timeoutSeconds wall seconds after which the run is stopped and counted as failed
     * @return how it went
     */
    RunReport run(Consumer<RunningServer> started, double timeoutSeconds) throws InterruptedException {
        String client;
        try {
            client = clientCommand(dir);
        } catch (IOException e) {
            return report(RunReport.failed("cannot read " + CLIENT_COMMAND + ": " + IoFailures.why(e), ExitStatus.STARTUP_FAILED));
        }
        RunningServer server;
        try {
            server = ServerLauncher.start(new String[] {"-p", dir.resolve(PROPERTIES).toString()},
                    Paths.get("").toAbsolutePath(), LaunchOptions.defaults().withPort(0).withView(this::watch)
                            .withClassLoader(loader).withPlans(plans).withHelperThreads(helpers));
        } catch (StartupException e) {
            return report(RunReport.failed("startup failed: " + e.getMessage(), e.getExitStatus()));
        }
        started.accept(server);
        ExternalClient external = null;
        try {
            if (client != null) {
                external = ExternalClient.start(client, dir, server);
            }
            long deadline = Double.isInfinite(timeoutSeconds) ? Long.MAX_VALUE
                    : System.nanoTime() + (long) (timeoutSeconds * 1e9);
            OptionalInt status = awaitExit(server, external, deadline);
            if (status.isEmpty() && external != null && external.hasExited()) {
                server.stop();
                return report(RunReport.failed("client failed: " + external.describeExit(), ExitStatus.CLIENT_FAILED));
            }
            if (status.isEmpty()) {
                server.stop();
                return report(RunReport.failed(String.format(Locale.ROOT, "timeout: still running after %.0f s of"
                        + " wall time", timeoutSeconds), RunReport.TIMED_OUT));
            }
            int exit = status.getAsInt();
            String reason = server.getStopReason();
            if (exit == ExitStatus.OK && external != null && failedFirst(external, reason)) {
                exit = ExitStatus.CLIENT_FAILED;
                reason = "client failed: " + external.describeExit();
            }
            List<RobotResult> results = external == null ? robots : withResults(robots, external.finish());
            // Which parameters a --client program reads is not known here.
            List<String> asked = external == null ? server.getSimulation().getAskedParameters().names() : null;
            return report(new RunReport(endTime, reason, exit, results, asked));
        } catch (IOException e) {
            server.stop();
            return report(RunReport.failed("the client could not be started: " + e.getMessage(), ExitStatus.STARTUP_FAILED));
        } finally {
            if (external != null) {
                external.stop();
            }
        }
    }

    /**
     * Waits until the server stops by itself; empty if the deadline passes first, or if the run's
     * client program has ended and the server has not stopped {@link ExternalClient#GRACE_SECONDS}
     * later (it left without a robot on the floor, which a run waiting for it would wait for forever).
     */
    private static OptionalInt awaitExit(RunningServer server, ExternalClient external, long deadline)
            throws InterruptedException {
        long clientGone = Long.MAX_VALUE;
        while (System.nanoTime() < deadline) {
            long wait = Math.min(deadline - System.nanoTime(), external == null ? Long.MAX_VALUE : POLL_NANOS);
            OptionalInt status = server.awaitExit(wait, TimeUnit.NANOSECONDS);
            if (status.isPresent()) {
                return status;
            }
            if (external != null && external.hasExited()) {
                external.seenEndedBeforeTheRun();
                clientGone = Math.min(clientGone, System.nanoTime());
                if (System.nanoTime() - clientGone > TimeUnit.SECONDS.toNanos(ExternalClient.GRACE_SECONDS)) {
                    return OptionalInt.empty();
                }
            }
        }
        return OptionalInt.empty();
    }

    /**
     * Whether the run's program failed while the run went on: it ended by itself with a status other
     * than 0, seen while the server ran or ending the run by leaving it deserted. (A program that ends
     * with an error once the server has closed its connection at the run's end has not failed the run.)
     */
    private static boolean failedFirst(ExternalClient external, String reason) throws InterruptedException {
        if (reason.equals(RunningServer.NOBODY_LEFT)) {
            // Its robot left: the program is ending, and how it ends tells whether that was asked.
            external.awaitExit(ExternalClient.GRACE_SECONDS);
        }
        return external.hasExited() && external.exitValue() != 0
                && (external.endedBeforeTheRun() || reason.equals(RunningServer.NOBODY_LEFT));
    }

    /** The {@code --client} command the run's folder holds, or null. */
    private static String clientCommand(Path dir) throws IOException {
        Path file = dir.resolve(CLIENT_COMMAND);
        return Files.exists(file) ? Files.readString(file, StandardCharsets.UTF_8).trim() : null;
    }

    /** The results an external client reported belong to its run: each robot gets them. */
    private static List<RobotResult> withResults(List<RobotResult> robots, Map<String, Double> reported) {
        List<RobotResult> out = new ArrayList<>();
        for (RobotResult r : robots) {
            Map<String, Double> results = new LinkedHashMap<>(r.results());
            results.putAll(reported);
            out.add(new RobotResult(r.name(), r.start(), r.end(), r.distance(), r.collisions(), r.firstCollisionTime(),
                    r.events(), results));
        }
        return out;
    }

    /**
     * The shutdown hook: waits until the server has started (if it is starting), then stops it cleanly
     * (as failed if the robot called System.exit) and waits until the run's results are written,
     * since the process ends when the hook returns.
     */
    private static void stopOnceStarted(CompletableFuture<RunningServer> started, CountDownLatch reported) {
        try {
            RunningServer server = started.get(START_WAIT_SECONDS, TimeUnit.SECONDS);
            if (server != null) {
                Optional<String> exitCall = ExitCaller.outsideTheSimulator();
                if (exitCall.isPresent()) {
                    server.stopForExitCall(exitCall.get());
                } else {
                    server.stop();
                }
                reported.await(START_WAIT_SECONDS, TimeUnit.SECONDS);
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
            robots = statistics.results(endTime);
            view.close();
        };
    }

    /** The robots' trails, once {@link #run} has returned (none if the server never started). */
    List<Trail> trails() {
        return trails;
    }

    private RunReport report(RunReport report) {
        if (statistics != null) {
            trails = statistics.trails();
        }
        try {
            report.write(dir);
            if (statistics != null) {
                TrailFile.write(dir, trails);
            }
        } catch (IOException e) {
            System.err.println("rp1.simulator.batch.SweepRun: cannot write the run's results in " + dir + ": "
                    + e.getMessage());
        }
        return report;
    }
}
