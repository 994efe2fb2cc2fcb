package rp1.rossum;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardOpenOption;
import java.util.Map;

/**
 * The run as a sweep's {@code --client} describes it in the environment: parameters and seed from
 * variables, results appended to the file one names (the sweep reads the last value of each name).
 */
final class EnvironmentRunContext implements RsRunContext {
    private final Map<String, String> environment;

    EnvironmentRunContext(Map<String, String> environment) {
        this.environment = Map.copyOf(environment);
    }

    @Override
    public String getParameter(String name) {
        return environment.get(RsRunContext.parameterVariable(name));
    }

    @Override
    public long getSeed() {
        String seed = environment.get(SEED_VARIABLE);
        if (seed == null) {
            return 0L;
        }
        try {
            return Long.parseLong(seed.trim());
        } catch (NumberFormatException e) {
            throw new IllegalStateException(SEED_VARIABLE + "=" + seed + ": not a seed", e);
        }
    }

    @Override
    public synchronized void reportResult(String name, double value) {
        String file = environment.get(RESULTS_VARIABLE);
        if (file == null) {
            return;
        }
        Path path = Paths.get(file);
        try {
            Files.write(path, (name + " " + value + "\n")
                    .getBytes(StandardCharsets.UTF_8), StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the result " + name + " to " + path + " (" + RESULTS_VARIABLE
                    + ")", e);
        }
    }
}
