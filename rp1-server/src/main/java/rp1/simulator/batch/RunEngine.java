package rp1.simulator.batch;

import java.io.IOException;
import java.util.List;

/** Carries out a sweep's runs one way or another ({@code --isolation}). Any thread; several runs at once. */
interface RunEngine {
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
}
