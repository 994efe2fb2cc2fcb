package rp1.simulator.world;

/**
 * The version of the world model, written into every recording of a run (docs/recording.md). A
 * replay runs the recorded inputs through this build's model; if the model computes differently, the
 * replay would silently be another run, so a recording of another version is refused.
 */
public final class WorldModel {
    /**
     * Raise it by one with every change that can make the same inputs give other events or another
     * end state: motion, collisions, sensors, placements, the order or timing of tasks. Version 2
     * seeds the world's random source with the run's seed mixed ({@link rp1.simulator.noise.SplitMix}).
     */
    public static final int VERSION = 2;

    private WorldModel() {
    }
}
