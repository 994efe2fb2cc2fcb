package rp1.simulator.batch;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import rp1.planparser.ParsedPlans;
import rp1.simulator.outcome.Trail;

/**
 * Carries out a sweep's runs one way or another ({@code --isolation}, or one given by a
 * {@link Factory}, such as rp1-spark's, which runs them on a Spark cluster). Any thread; several
 * runs at once.
 */
public interface RunEngine extends AutoCloseable {
    /** How a run went, and its robots' trails. */
    record Ran(RunReport report, List<Trail> trails) {
    }

    /**
     * Carries out {@code run}, whose folder holds its {@code run.ini}.
     *
     * @return how it went; a run stopped by {@link #stopAll()} ends with reason {@code stopped}
     */
    Ran run(Batch.Run run) throws IOException, InterruptedException;

    /** Stops the runs going, as Ctrl-C would stop a server; returns at once. */
    void stopAll();

    /**
     * Whether the engine's first run is best carried out alone: true for runs in this process, whose
     * first run loads and compiles what every later run shares (two cold runs at once only wait for
     * each other's class loading and for the one compiler thread).
     */
    default boolean firstRunWarmsUp() {
        return false;
    }

    /**
     * Whether every run the engine carries out ends within the sweep's --timeout and the few seconds
     * of a stop once it has begun: true for runs in this process and in processes of their own, so
     * that a sweep with no run starting or ending for longer takes its process for stuck instead of
     * waiting for ever. Not for runs that may wait to begin (for a cluster's executors).
     */
    default boolean runsEndWithinTheirTimeout() {
        return false;
    }

    /**
     * Releases what the engine kept for its runs (the loader the runs shared, and its open jars) once
     * no run is going or will start: a JVM that runs one sweep after another keeps nothing of the
     * ones that ended. Safe to call more than once.
     */
    @Override
    default void close() {
    }

    /** A line for the sweep's user on how the runs were carried out, once they have been; or null. */
    default String note() {
        return null;
    }

    /**
     * The sweep's engine for runs in this process ({@code --isolation loader}): each with the robot's
     * classes as a process of its own would have them (loaded anew, unless none keeps state in a
     * static field) and a world of its own. rp1-spark's executors run their tasks with it.
     *
     * @param robotClasses the robots' classes (dlcName), found through {@code parent}
     */
    static RunEngine inThisProcess(List<String> robotClasses, ClassLoader parent, double timeoutSeconds) {
        return new LoaderRuns(robotClasses, parent, timeoutSeconds, new ParsedPlans(), null);
    }

    /**
     * The sweep's engine for runs in processes of their own ({@code --isolation process}): {@link
     * SweepRun} with the quick compiler, stopped as Ctrl-C would stop it after the timeout. rp1-spark's
     * executors run such tasks with it.
     *
     * @param robotClassPath the robots' classes ({@code -cp}), absolute
     */
    static RunEngine inProcesses(double timeoutSeconds, List<Path> robotClassPath) {
        return new ProcessRuns(timeoutSeconds, robotClassPath);
    }

    /** Makes the engine for a sweep once the sweep is prepared (its runs and robot class path known). */
    interface Factory {
        /**
         * @throws SweepException saying why the runs cannot be carried out this way
         */
        RunEngine open(Batch batch) throws SweepException;
    }
}
