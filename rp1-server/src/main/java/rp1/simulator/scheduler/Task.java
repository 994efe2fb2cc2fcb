package rp1.simulator.scheduler;

/**
 * Work the scheduler runs at a simulation time: a timeout falling due, a heartbeat, a motion step,
 * a placement. Tasks run one at a time on the scheduler thread, to completion.
 */
@FunctionalInterface
public interface Task {
    /**
     * Does the work.
     *
     * @param simTime the simulation time the task runs at (its scheduled time, or the current time
     *                for an immediate task)
     */
    void run(double simTime);
}
