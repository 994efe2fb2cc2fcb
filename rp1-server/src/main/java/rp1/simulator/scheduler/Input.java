package rp1.simulator.scheduler;

/**
 * Something that reaches the simulation from outside (a client's request, its body, its departure,
 * a mouse click on the view): queued by the thread it arrives on and applied by the thread running
 * tasks at the next boundary between two tasks ({@link InputQueue}).
 */
public interface Input {
    /** Who it comes from: a client's number (1, 2, ...), or 0 for the view. */
    int source();

    /** Whether it is a client leaving; departures are applied before everything else at a boundary. */
    default boolean isDeparture() {
        return false;
    }

    /** Applies it, at simulation time {@code simTime}, on the thread running tasks. */
    void apply(double simTime);
}
