package rp1.simulator.world;

import java.util.ArrayList;
import java.util.List;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;

/**
 * The one recycled motion task of the simulation (behavior.md section 4.4). When it runs at time T it
 * evaluates every robot that needs it: motions are brought to T and waiting requests started, robots
 * about to touch each other are stopped before they do, then sensors are read and ended motions
 * reported. It queues itself again for the earliest next evaluation any robot asked for.
 */
final class MotionStepper implements Task {
    private final World world;
    private final Scheduler scheduler;
    private final double interval;
    private TaskHandle queued = TaskHandle.NONE;

    MotionStepper(World world, Scheduler scheduler, double interval) {
        this.world = world;
        this.scheduler = scheduler;
        this.interval = interval;
    }

    /**
     * Queues the task at {@code time} unless it is already queued: then the entry already there stands,
     * so a request for a moving robot takes effect at its next step (docs/behavior.md section 4.4).
     */
    void wake(double time) {
        if (!queued.isScheduled()) {
            queued = scheduler.schedule(time, Scheduler.NORMAL, this);
        }
    }

    /** The task is removed when no robot is left. */
    void cancel() {
        queued.cancel();
    }

    @Override
    public void run(double time) {
        List<Robot> active = new ArrayList<>();
        for (Robot r : world.getRobots()) {
            if (r.needsProcessing()) {
                active.add(r);
            }
        }
        if (active.isEmpty()) {
            return;
        }
        for (Robot r : active) {
            r.advance(time);
            if (r.hasPendingRequest()) {
                r.startPendingMotion(time, world.getWalls());
            }
        }
        List<Robot> placed = world.getPlacedRobots();
        if (placed.size() > 1 && world.robotsInteract()) {
            RobotContacts.resolve(placed, time, time + interval + RobotContacts.LOOK_AHEAD);
        }
        double next = Double.POSITIVE_INFINITY;
        for (Robot r : active) {
            r.sense(time, world.getPlan(), world.obstaclesFor(r, placed));
            double n = r.finish(time, interval);
            if (!Double.isNaN(n)) {
                next = Math.min(next, n);
            }
        }
        for (Robot r : placed) {
            if (r.isTouched()) {
                r.pressTouched(time);
            }
        }
        if (next < Double.POSITIVE_INFINITY) {
            wake(next);
        }
        world.changed(time);
    }
}
