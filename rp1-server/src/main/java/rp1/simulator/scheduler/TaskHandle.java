package rp1.simulator.scheduler;

/**
 * A task that was scheduled, as the scheduler hands it back (MASON's {@code Stoppable}): the one way
 * to take it out of the queue again, and to ask whether it is still waiting. A handle is good for one
 * queuing; a task that queues itself again gets a new handle.
 */
public interface TaskHandle {
    /**
     * Takes the task out of the queue if it is still waiting.
     *
     * @return whether it was waiting (false if it already ran, is running or was cancelled)
     */
    boolean cancel();

    /** Whether the task is still waiting to run. */
    boolean isScheduled();

    /** A handle for nothing: never scheduled, cancelling it does nothing. */
    TaskHandle NONE = new TaskHandle() {
        @Override
        public boolean cancel() {
            return false;
        }

        @Override
        public boolean isScheduled() {
            return false;
        }
    };
}
