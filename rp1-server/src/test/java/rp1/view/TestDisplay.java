package rp1.view;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.junit.jupiter.api.Assumptions;

/**
 * The X display a window test draws on: the one {@code DISPLAY} names, or else a virtual one (Xvfb)
 * started for the test and stopped when it is closed. When neither can be had, the test is aborted
 * with the reason, so that it is reported as skipped rather than failed or silently passed.
 */
final class TestDisplay implements AutoCloseable {
    private static final long START_SECONDS = 20;
    private static final long STOP_SECONDS = 10;

    private final String name;
    private final Process xvfb;

    private TestDisplay(String name, Process xvfb) {
        this.name = name;
        this.xvfb = xvfb;
    }

    /**
     * The display named by {@code DISPLAY} if it is set and answers; otherwise an Xvfb found on
     * {@code PATH}, started on a display number it chooses itself (so parallel runs on one machine do
     * not clash), with its messages in {@code logFile}. Aborts the calling test if there is neither.
     */
    static TestDisplay openOrSkip(Path logFile) throws IOException, InterruptedException {
        String display = System.getenv("DISPLAY");
        String without;
        if (display == null || display.isEmpty()) {
            without = "DISPLAY is not set";
        } else if (XDisplayAddress.answers(display)) {
            return new TestDisplay(display, null);
        } else {
            // A Gradle daemon keeps the DISPLAY it was started with, which may be long gone.
            without = "DISPLAY=" + display + " does not answer";
        }
        Optional<Path> xvfb = onPath("Xvfb");
        if (xvfb.isEmpty()) {
            return skip(without + " and Xvfb is not on the PATH (Debian: apt-get install -y xvfb)");
        }
        return start(xvfb.get(), without, logFile);
    }

    /**
     * Aborts the test with {@code why}, also printed: the test summary counts skipped tests but the
     * console launcher's summary does not say why they were skipped.
     */
    private static TestDisplay skip(String why) {
        String message = "no X display for the window test, so it is skipped: " + why;
        System.err.println(message);
        return Assumptions.abort(message);
    }

    private static Optional<Path> onPath(String program) {
        String path = System.getenv("PATH");
        if (path == null) {
            return Optional.empty();
        }
        for (String dir : path.split(File.pathSeparator)) {
            Path candidate = Paths.get(dir.isEmpty() ? "." : dir, program);
            if (Files.isRegularFile(candidate) && Files.isExecutable(candidate)) {
                return Optional.of(candidate);
            }
        }
        return Optional.empty();
    }

    /**
     * Starts Xvfb with {@code -displayfd 1}: once it accepts clients it writes the number of the
     * display it took to its standard output.
     */
    private static TestDisplay start(Path xvfb, String without, Path logFile) throws IOException, InterruptedException {
        Files.createDirectories(logFile.toAbsolutePath().getParent());
        Process p = new ProcessBuilder(xvfb.toString(), "-displayfd", "1", "-screen", "0", "1280x1024x24",
                "-nolisten", "tcp")
                .redirectError(logFile.toFile())
                .start();
        CompletableFuture<String> number = CompletableFuture.supplyAsync(() -> firstLine(p));
        try {
            String n = number.get(START_SECONDS, TimeUnit.SECONDS);
            // Null: Xvfb ended without taking a display.
            if (n != null && n.matches("\\d+")) {
                return new TestDisplay(":" + n, p);
            }
        } catch (ExecutionException | TimeoutException e) {
            // Reported below, with Xvfb's own messages.
        }
        stop(p);
        return skip(without + " and " + xvfb + " did not start a display (waited up to " + START_SECONDS
                + " s); it said: " + Files.readString(logFile, StandardCharsets.UTF_8).trim());
    }

    private static String firstLine(Process p) {
        try {
            return new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.US_ASCII)).readLine();
        } catch (IOException e) {
            return null;
        }
    }

    private static void stop(Process p) throws InterruptedException {
        p.destroy();
        if (!p.waitFor(STOP_SECONDS, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor(STOP_SECONDS, TimeUnit.SECONDS);
        }
    }

    /** The value for {@code DISPLAY}, e.g. {@code :99}. */
    String name() {
        return name;
    }

    /** Whether this display was started for the test (rather than given by {@code DISPLAY}). */
    boolean isVirtual() {
        return xvfb != null;
    }

    /**
     * Stops the virtual display, if one was started. An interrupt while waiting for it to stop is
     * kept on the thread rather than thrown, so that it cannot hide the test's own failure.
     */
    @Override
    public void close() {
        if (xvfb != null) {
            try {
                stop(xvfb);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
