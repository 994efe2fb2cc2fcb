package rp1.simulator.scheduler;

/**
 * Work the scheduler runs at a simulation time: a timeout falling due, a heartbeat, a motion step,
 * a placement. Tasks run one at a time, to completion, on whichever thread holds the scheduler's
 * right to run them (its dispatch loop, or a transport thread that released the interlock or handed
 * over inputs; see {@link Scheduler}); a task never needs to know which.
 */
@FunctionalInterface
public interface Task {
    /**
     * Does the work.
     *
     * @param simTime the simulation time the task runs at: its scheduled time, or for an immediate
     *                task the time it was stamped with when it was queued
     */
    void run(double simTime);
}
