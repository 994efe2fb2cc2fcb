package rp1.simulator.scheduler;

/**
 * Wall-clock time for pacing the simulation, in nanoseconds from an arbitrary origin. Injected so
 * tests can drive pacing with a fake clock; the wall clock only decides when tasks run, never what
 * they compute.
 */
@FunctionalInterface
public interface TimeSource {
    /** The system's monotonic clock. */
    TimeSource SYSTEM = System::nanoTime;

    long nanoTime();
}
