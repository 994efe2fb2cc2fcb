package rp1.spark;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import rp1.simulator.batch.Batch;
import rp1.simulator.batch.RunEngine;

/**
 * A run in a Java process of its own on the executor's machine ({@code --isolation process}), as the
 * sweep runs one on its own machine ({@link RunEngine#inProcesses}): {@code java
 * rp1.simulator.batch.SweepRun DIR [-cp ROBOT]} with the executor's Java and class path, stopped as
 * Ctrl-C would stop it if it outlasts the timeout or the task is cancelled.
 */
final class ProcessRun implements LocalRun {
    private static final long serialVersionUID = 1L;

    @Override
    public RunEngine.Ran run(Path dir, List<Path> robotClassPath, double timeoutSeconds) throws IOException, InterruptedException {
        try (RunEngine engine = RunEngine.inProcesses(timeoutSeconds, robotClassPath)) {
            return engine.run(new Batch.Run(Map.of(), 0, "", dir));
        }
    }
}
