package rp1.simulator.world;

/**
 * Told when the picture of the world changed: robots moved at a motion step, joined, left, were
 * placed, or targets or trails changed. Called on the scheduler thread; implementations must return
 * quickly (take a snapshot, hand it over, return) and must not change the world.
 */
@FunctionalInterface
public interface WorldListener {
    void worldChanged(World world, double simTime);
}
