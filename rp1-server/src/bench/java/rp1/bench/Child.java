package rp1.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

/** A benchmark part in a JVM of its own (its memory figures are then its own), on the bench's class path. */
final class Child {
    private Child() {
    }

    /** Runs {@code main} with {@code args} under {@code -Xmx}; each output line goes to {@code lines}; returns the exit status. */
    static int run(String xmx, Class<?> main, Consumer<String> lines, String... args)
            throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(Arrays.asList(
                Paths.get(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + xmx, "-Xss4m", "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                main.getName()));
        command.addAll(Arrays.asList(args));
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
