package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;

import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.scheduler.Task;
import rp1.simulator.scheduler.TaskHandle;

/**
 * Motion evaluation (docs/behavior.md sections 4.4 and 5.4). Each robot that needs it (moving, a
 * request to start, just placed, or run into by another robot) has its own next evaluation time; one
 * recycled task runs at the earliest of them and evaluates the robots due then, in joining order:
 * motions brought to the time and waiting requests started, the coming interval searched for contacts
 * with nearby robots, sensors read and ended motions reported. A moving robot is evaluated every
 * modelling interval from its own last evaluation and at the end of its motion, as a robot alone was
 * in RP1 0.60; other robots do not add evaluations to it (0.60 evaluated every moving robot whenever
 * any robot needed it, which made a crowd cost the square of its size).
 *
 * <p>A request for a moving robot takes effect at its next evaluation; for a robot at rest, at once.
 */
final class MotionStepper implements Task {
    private static final Comparator<Robot> DUE =
            Comparator.comparingDouble(Robot::nextEvaluation).thenComparingInt(Robot::getNumber);

    private final World world;
    private final Scheduler scheduler;
    private final double interval;
    /** Runs of this task so far: the order in which motions started and searches were made. */
    private long runs;
    private final PriorityQueue<Robot> due = new PriorityQueue<>(DUE);
    private TaskHandle queued = TaskHandle.NONE;
    private double queuedTime = Double.NaN;

    MotionStepper(World world, Scheduler scheduler, double interval) {
        this.world = world;
        this.scheduler = scheduler;
        this.interval = interval;
    }

    /** The robot is evaluated at {@code time}, or earlier if it already is due earlier. */
    void evaluateBy(Robot r, double time) {
        if (r.isDue() && r.nextEvaluation() <= time) {
            return;
        }
        if (r.isDue()) {
            due.remove(r);
        }
        r.setNextEvaluation(time);
        due.add(r);
        requeue();
    }

    /**
     * A request for the robot: a robot at rest is evaluated at {@code time}; one already due keeps its
     * time (a moving robot starts the new motion at its next step, as in RP1 0.60).
     */
    void wake(Robot r, double time) {
        if (!r.isDue()) {
            evaluateBy(r, time);
        }
    }

    /** The robot leaves: no more evaluations. */
    void forget(Robot r) {
        if (r.isDue()) {
            due.remove(r);
            r.clearNextEvaluation();
            requeue();
        }
    }

    /** Keeps the task queued at the earliest evaluation due. */
    private void requeue() {
        if (due.isEmpty()) {
            queued.cancel();
            return;
        }
        double first = due.peek().nextEvaluation();
        if (queued.isScheduled() && queuedTime == first) {
            return;
        }
        queued.cancel();
        queuedTime = first;
        queued = scheduler.schedule(first, Scheduler.NORMAL, this);
    }

    @Override
    public void run(double time) {
        runs++;
        List<Robot> group = new ArrayList<>();
        while (!due.isEmpty() && due.peek().nextEvaluation() <= time) {
            Robot r = due.poll();
            r.clearNextEvaluation();
            group.add(r);
        }
        List<Robot> active = new ArrayList<>();
        for (Robot r : group) {
            if (r.needsProcessing()) {
                active.add(r);
            }
        }
        for (Robot r : active) {
            r.advance(time);
            if (r.hasPendingRequest()) {
                r.startPendingMotion(time, world.wallsForMotion(r, r.pendingRequest()));
                r.setMotionStartedIn(runs);
                // Filed where the new motion can take it before any contact search looks it up.
                world.indexRobot(r, time, interval);
            }
        }
        world.searchContacts(active, time, time + interval + RobotContacts.LOOK_AHEAD, runs);
        for (Robot r : active) {
            r.sense(time, world.getPlan(), world.obstaclesFor(r, time));
            double next = r.finish(time, interval);
            world.indexRobot(r, time, interval);
            if (!Double.isNaN(next)) {
                evaluateBy(r, next);
            }
        }
        for (Robot r : group) {
            if (r.isTouched()) {
                r.pressTouched(time);
                if (r.isTouched() && !r.isMoving()) {
                    evaluateBy(r, r.nextTouch());
                }
            }
        }
        requeue();
        world.changed(time);
    }
}
