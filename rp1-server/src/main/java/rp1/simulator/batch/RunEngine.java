package rp1.simulator.batch;

import java.io.IOException;

/**
 * Carries out a sweep's runs one way or another: the sweep's own (a process per run) or one given by
 * {@link Factory}, such as rp1-spark's, which runs them on a Spark cluster. Any thread; several runs
 * at once.
 */
public interface RunEngine {
    /**
     * Carries out {@code run}, whose folder holds its {@code run.ini}, and leaves its results there.
     *
     * @return how it went; a run stopped by {@link #stopAll()} ends with reason {@code stopped}
     */
    RunReport run(Batch.Run run) throws IOException, InterruptedException;

    /** Stops the runs going, as Ctrl-C would stop a server; returns at once. */
    void stopAll();

    /** Makes the engine for a sweep once the sweep is prepared (its runs and robot class path known). */
    interface Factory {
        /**
         * @throws SweepException saying why the runs cannot be carried out this way
         */
        RunEngine open(Batch batch) throws SweepException;
    }
}
