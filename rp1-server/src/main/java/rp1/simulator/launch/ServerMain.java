package rp1.simulator.launch;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Optional;

import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ServerArguments;

/**
 * What {@code rp1.Server.main} does: start a server in the working directory, stop it cleanly on
 * Ctrl-C or SIGTERM (clients closed, log flushed), and return the exit status. A server that cannot
 * start prints one line saying why on standard error; an {@code Error} on any thread (out of memory,
 * say) ends the process with a message and {@link ExitStatus#FATAL_ERROR} rather than leave it
 * holding the port while serving nobody.
 */
public final class ServerMain {
    private ServerMain() {
    }

    /**
     * Runs a server until it stops; returns the process's exit status. An {@code Error} on any thread
     * ends the process with {@link ExitStatus#FATAL_ERROR}.
     */
    public static int run(String[] args) {
        FatalErrors.install();
        try {
            ServerArguments arguments = ServerArguments.parse(args);
            if (arguments.help) {
                System.out.println(ServerArguments.USAGE);
                return ExitStatus.OK;
            }
            if (arguments.headless) {
                // Read by AWT once, when it first starts; nothing has started it yet.
                System.setProperty("java.awt.headless", "true");
            }
        } catch (ConfigException e) {
            System.err.println("rp1.Server: " + e.getMessage());
            return ExitStatus.STARTUP_FAILED;
        }
        Path workingDirectory = Paths.get("").toAbsolutePath();
        RunningServer server;
        try {
            server = ServerLauncher.start(args, workingDirectory);
        } catch (StartupException e) {
            System.err.println("rp1.Server: " + e.getMessage());
            return e.getExitStatus();
        }
        return awaitExit(server);
    }

    /**
     * Waits until {@code server} stops; Ctrl-C or SIGTERM meanwhile stop it cleanly first (clients
     * closed, log, recording and event log flushed). Returns the exit status.
     */
    public static int awaitExit(RunningServer server) {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> stopInHook(server), "shutdown hook"));
        try {
            return server.awaitExit();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return stopQuietly(server, ExitCaller.outsideTheSimulator());
        }
    }

    /**
     * Stops the server as the process ends. A loaded robot that called {@code System.exit} would end
     * the process with the status it chose (0, as often as not) although its run failed: once the
     * server has stopped and closed its files, the process ends with the run's status instead,
     * {@link ExitStatus#CLIENT_FAILED}, without waiting for the other hooks (the robot's own, files it
     * marked to delete on exit).
     */
    private static void stopInHook(RunningServer server) {
        Optional<String> exitCall = ExitCaller.outsideTheSimulator();
        int status = stopQuietly(server, exitCall);
        if (exitCall.isPresent()) {
            System.out.flush();
            System.err.flush();
            Runtime.getRuntime().halt(status);
        }
    }

    private static int stopQuietly(RunningServer server, Optional<String> exitCall) {
        try {
            return exitCall.isPresent() ? server.stopForExitCall(exitCall.get()) : server.stop();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return ExitStatus.OK;
        }
    }
}
