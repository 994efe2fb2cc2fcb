package rp1.simulator.world;

/**
 * Told when the picture of the world changed: robots moved at a motion step, joined, left, were
 * placed, or targets or trails changed. Called on the thread running the simulation's tasks (never
 * on a view's thread); implementations must return quickly (note the change, or take a snapshot and
 * hand it over) and must not change the world.
 */
@FunctionalInterface
public interface WorldListener {
    /** The world changed at {@code simTime} (NaN when the change was not at a motion step). */
    void worldChanged(World world, double simTime);
}
