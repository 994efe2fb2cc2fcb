package rp1.simulator.outcome;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One robot of a run: where it started and where it was at the run's end, what happened to it, and
 * the results it reported of its own.
 *
 * @param name               the robot's name (its body's), with {@code #N} added when robots share a name
 * @param start              where it was first placed (NaN if never)
 * @param end                where it was at the run's end time
 * @param distance           how far its body origin travelled until the end time, metres
 * @param collisions         how many of its motions ended in a collision
 * @param firstCollisionTime simulated seconds of the first of them, NaN if none
 * @param events             how many events its client was sent
 * @param results            what it reported with {@code reportRunResult}, in the order first reported
 */
public record RobotResult(String name, Pose start, Pose end, double distance, int collisions,
                          double firstCollisionTime, long events, Map<String, Double> results) {
    /** A pose in the world: metres and radians. */
    public record Pose(double x, double y, double heading) {
        /** No pose: the robot was never placed. */
        public static final Pose NONE = new Pose(Double.NaN, Double.NaN, Double.NaN);
    }

    /** Copies the results. */
    public RobotResult {
        results = Collections.unmodifiableMap(new LinkedHashMap<>(results));
    }
}
