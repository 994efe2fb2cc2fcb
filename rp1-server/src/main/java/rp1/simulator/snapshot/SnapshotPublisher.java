package rp1.simulator.snapshot;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import rp1.simulator.Simulation;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;
import rp1.simulator.world.World;
import rp1.simulator.world.WorldListener;

/**
 * Keeps the latest snapshot of the world for an observer on another thread (the view's animation
 * timer). The observer {@link #poll() polls} at its own pace; if the world changed since the last
 * snapshot, a poll queues one capture, an observer task that takes the next snapshot on the thread
 * running the simulation's tasks. So the simulation pays for at most one snapshot per poll, and
 * nothing at all while nobody polls or nothing changes; a slow or frozen observer merely polls less
 * often.
 *
 * <p>The capture sends nothing and changes nothing, and observers neither move the clock nor reorder
 * model tasks, so observing never changes what the clients are told. While the clock is stopped (the
 * interlock waits for a client) the capture waits too, like every task.
 */
public final class SnapshotPublisher implements WorldListener, AutoCloseable {
    private final World world;
    private final Scheduler scheduler;
    private final AtomicBoolean changed = new AtomicBoolean(true);
    private final AtomicReference<WorldSnapshot> latest;
    private final Task capture = this::capture;
    private TaskHandle queued = TaskHandle.NONE;
    /** Read and written only under this publisher's lock. */
    private boolean closed;

    /** Starts observing the simulation's world; the first snapshot shows the plan alone. */
    public SnapshotPublisher(Simulation simulation) {
        this.world = simulation.getWorld();
        this.scheduler = simulation.getScheduler();
        this.latest = new AtomicReference<>(WorldSnapshot.planOnly(world.getPlan()));
        world.addListener(this);
    }

    /** On the thread running tasks: the picture is out of date. */
    @Override
    public void worldChanged(World w, double simTime) {
        changed.set(true);
    }

    /**
     * The latest snapshot; if the world has changed since it was taken, a fresh one is requested and
     * a later poll returns it. Any thread; never blocks. After {@link #close()}, always the last one.
     */
    public WorldSnapshot poll() {
        synchronized (this) {
            if (!closed && changed.get() && !queued.isScheduled()) {
                queued = scheduler.observeNow(capture);
            }
        }
        return latest.get();
    }

    private void capture(double simTime) {
        if (changed.getAndSet(false)) {
            latest.set(WorldSnapshot.of(world, simTime));
        }
    }

    /** Stops observing; a capture still queued is withdrawn. */
    @Override
    public synchronized void close() {
        closed = true;
        world.removeListener(this);
        queued.cancel();
    }
}
