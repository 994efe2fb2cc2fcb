package rp1.simulator.batch;

import java.io.IOException;

/** Carries out a sweep's runs one way or another ({@code --isolation}). Any thread; several runs at once. */
interface RunEngine {
    /**
     * Carries out {@code run}, whose folder holds its {@code run.ini}.
     *
     * @return how it went; a run stopped by {@link #stopAll()} ends with reason {@code stopped}
     */
    RunReport run(Batch.Run run) throws IOException, InterruptedException;

    /** Stops the runs going, as Ctrl-C would stop a server; returns at once. */
    void stopAll();
}
