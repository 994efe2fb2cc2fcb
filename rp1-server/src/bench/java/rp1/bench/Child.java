package rp1.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import rp1.simulator.launch.JavaCommand;

/**
 * A benchmark part in a JVM of its own (its memory figures are then its own), on the bench's class path,
 * with the options the installed simulator runs with ({@link JavaCommand#simulatorOptions()}).
 */
final class Child {
    private Child() {
    }

    /** Runs {@code main} with {@code args} under {@code -Xmx}; each output line goes to {@code lines}; returns the exit status. */
    static int run(String xmx, Class<?> main, Consumer<String> lines, String... args)
            throws IOException, InterruptedException {
        List<String> options = new ArrayList<>(JavaCommand.simulatorOptions());
        options.addAll(List.of("-Xmx" + xmx, "-Xss4m"));
        return run(JavaCommand.of(options, main.getName(), args), lines);
    }

    /** Runs {@code command}, its errors merged into its output; each output line goes to {@code lines}; returns the exit status. */
    static int run(List<String> command, Consumer<String> lines) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                lines.accept(line);
            }
        }
        return p.waitFor();
    }
}
