package rp1.spark;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import rp1.simulator.batch.Batch;
import rp1.simulator.batch.RunEngine;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ResourceLocator;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.launch.ClientClassPath;
import rp1.simulator.batch.SweepRun;

/**
 * A run in the executor's own JVM ({@code --isolation loader}, the default), as the sweep runs one in
 * its own: a class loader of its own for the robot's classes and a world of its own
 * ({@link RunEngine#inThisProcess}). The robots are those its {@code run.ini} loads.
 */
final class IsolatedRun implements LocalRun {
    private static final long serialVersionUID = 1L;

    @Override
    public RunEngine.Ran run(Path dir, List<Path> robotClassPath, double timeoutSeconds)
            throws IOException, InterruptedException {
        // The loader that brought this task: the executor's, with the job's jars (spark-submit --jars).
        ClassLoader loader = ClientClassPath.loader(robotClassPath, IsolatedRun.class.getClassLoader());
        List<String> robots;
        try {
            ResourceLocator.Found ini = new ResourceLocator(dir, loader).properties(dir.resolve(SweepRun.PROPERTIES).toString());
            robots = ServerConfig.from(ResourceLocator.parseProperties(ini), ini.location, null).dlcNames;
        } catch (ConfigException e) {
            throw new IOException("the run's properties: " + e.getMessage(), e);
        }
        try (RunEngine engine = RunEngine.inThisProcess(robots, loader, timeoutSeconds)) {
            return engine.run(new Batch.Run(Map.of(), 0, "", dir));
        }
    }
}
