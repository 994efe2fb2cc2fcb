package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import rp1.rossum.RsRunContext;
import rp1.simulator.launch.RunningServer;

/**
 * A sweep's {@code --client}: the program that is a run's robot, in any language, started once the
 * run's server listens, with the run in its environment ({@link RsRunContext}: {@code RP1_PORT},
 * {@code RP1_HOST}, {@code RP1_SEED}, {@code RP1_PARAM_NAME}, {@code RP1_RESULTS}); what it prints
 * goes to {@code client.txt} in the run's folder. It is stopped when the run ends. The results it
 * reports are lines {@code NAME VALUE} appended to the file {@code RP1_RESULTS} names; the last
 * value of a name wins.
 */
final class ExternalClient {
    /** What the client printed, in the run's folder. */
    static final String OUTPUT = "client.txt";
    /** The results it reported, in the run's folder. */
    static final String RESULTS = "client-results.txt";
    /** The environment variable with the server's address. */
    static final String HOST_VARIABLE = "RP1_HOST";
    /** How long the program may take to end when asked, and the run to end once the program has. */
    static final long GRACE_SECONDS = 2;

    private final Process process;
    private final Path results;
    private final Path output;
    private boolean endedBeforeTheRun;

    private ExternalClient(Process process, Path results, Path output) {
        this.process = process;
        this.results = results;
        this.output = output;
    }

    /** Starts {@code command} (split at white space) for the run in {@code dir} served by {@code server}. */
    static ExternalClient start(String command, Path dir, RunningServer server) throws IOException {
        Path results = dir.resolve(RESULTS);
        Files.deleteIfExists(results);
        List<String> words = Arrays.asList(command.trim().split("\\s+"));
        ProcessBuilder b = new ProcessBuilder(words).redirectErrorStream(true)
                .redirectOutput(dir.resolve(OUTPUT).toFile());
        Map<String, String> env = b.environment();
        env.keySet().removeIf(k -> k.startsWith(RsRunContext.PARAMETER_PREFIX));
        env.put(RsRunContext.PORT_VARIABLE, Integer.toString(server.getPort()));
        env.put(HOST_VARIABLE, "127.0.0.1");
        env.put(RsRunContext.SEED_VARIABLE, Long.toString(server.getSimulation().getSeed()));
        env.put(RsRunContext.RESULTS_VARIABLE, results.toString());
        server.getConfig().parameters.forEach((name, value) -> env.put(RsRunContext.parameterVariable(name), value));
        return new ExternalClient(b.start(), results, dir.resolve(OUTPUT));
    }

    /** Whether the program has ended. */
    boolean hasExited() {
        return !process.isAlive();
    }

    /** Waits at most {@code seconds} for the program to end by itself. */
    void awaitExit(long seconds) throws InterruptedException {
        process.waitFor(seconds, TimeUnit.SECONDS);
    }

    /** The program's exit status, once it has ended. */
    int exitValue() {
        return process.exitValue();
    }

    /** The run saw the program ended while the server was still running. */
    void seenEndedBeforeTheRun() {
        endedBeforeTheRun = true;
    }

    /** Whether the program was seen ended while the server was still running. */
    boolean endedBeforeTheRun() {
        return endedBeforeTheRun;
    }

    /** How the program ended, with the last line it printed, for a run's reason. */
    String describeExit() {
        return "the program ended with status " + process.exitValue() + " before the run did: "
                + RunReport.lastLine(output);
    }

    /**
     * Stops the program (the run is over) and returns the results it reported: the last value of
     * each name, in the order first reported.
     */
    Map<String, Double> finish() throws IOException, InterruptedException {
        stop();
        Map<String, Double> out = new LinkedHashMap<>();
        List<String> lines;
        try {
            lines = Files.readAllLines(results, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            return out;
        }
        for (String line : lines) {
            String[] f = line.trim().split("\\s+");
            if (f.length == 2) {
                double v = Numbers.parse(f[1]);
                if (!Double.isNaN(v)) {
                    out.put(f[0], v);
                }
            }
        }
        return out;
    }

    /** Stops the program if it is still going: asked first, then forced. */
    void stop() throws InterruptedException {
        ProcessRuns.stop(process, GRACE_SECONDS);
    }
}
