package rp1.simulator;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;
import rp1.simulator.world.World;
import rp1.simulator.world.WorldListener;

/**
 * Runs an observer at multiples of a period of simulated time, but only at those multiples by which
 * the world has changed since the observer last ran: a world at rest is not kept busy, and observers
 * alone never drive a lockstep clock forward by more than one period. The observer runs on the thread
 * running tasks, after every model task due at its time, so it sees everything that happened up to it.
 */
final class ChangeObserver implements WorldListener, Task {
    private final World world;
    private final Scheduler scheduler;
    private final double period;
    private final Task observer;
    private TaskHandle queued = TaskHandle.NONE;
    private boolean changed;
    private boolean closed;

    ChangeObserver(World world, Scheduler scheduler, double period, Task observer) {
        if (!(period > 0.0) || Double.isInfinite(period)) {
            throw new IllegalArgumentException("period must be positive and finite, got " + period);
        }
        this.world = world;
        this.scheduler = scheduler;
        this.period = period;
        this.observer = observer;
        world.addListener(this);
    }

    @Override
    public synchronized void worldChanged(World w, double simTime) {
        changed = true;
        if (!closed && !queued.isScheduled()) {
            double now = Double.isNaN(simTime) ? scheduler.now() : simTime;
            queued = scheduler.observeAt(Math.ceil(now / period) * period, this);
        }
    }

    @Override
    public void run(double simTime) {
        synchronized (this) {
            if (!changed || closed) {
                return;
            }
            changed = false;
            queued = scheduler.observeAt((Math.round(simTime / period) + 1) * period, this);
        }
        observer.run(simTime);
    }

    /** No more observations. */
    synchronized void close() {
        closed = true;
        world.removeListener(this);
        queued.cancel();
    }
}
