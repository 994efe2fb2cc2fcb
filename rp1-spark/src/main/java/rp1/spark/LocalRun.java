package rp1.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.Path;
import java.util.List;

import rp1.simulator.batch.RunEngine;

/**
 * How an executor carries out one run whose folder holds its {@code run.ini}: as the sweep's own
 * engine would on one machine ({@code --isolation}). It leaves the run's files in the folder and
 * returns its report (a failed one when the run failed by itself) and trails; it throws only when
 * this machine could not carry it out at all.
 */
interface LocalRun extends Serializable {
    /**
     * @param robotClassPath where the robot's classes are on this machine (empty: the simulator's own)
     * @param timeoutSeconds wall seconds after which the run is stopped and reported as failed
     */
    RunEngine.Ran run(Path dir, List<Path> robotClassPath, double timeoutSeconds) throws IOException, InterruptedException;
}
