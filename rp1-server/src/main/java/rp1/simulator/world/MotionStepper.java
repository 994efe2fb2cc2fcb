package rp1.simulator.world;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleConsumer;

import rp1.rossum.RsPlan;
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
 * What is near a robot comes from the {@link Surroundings}; each robot's next evaluation time is kept
 * here, by robot number.
 */
final class MotionStepper implements Task {
    private final Scheduler scheduler;
    private final double interval;
    private final RsPlan plan;
    private final Surroundings surroundings;
    private final RobotContacts contacts;
    /** Told the time after every run: the picture changed. */
    private final DoubleConsumer changed;
    /** Runs of this task so far: the order in which motions started and searches were made. */
    private long runs;
    /** The robots due for evaluation. */
    private final DueRobots due = new DueRobots();
    /** The robots of the run under way, and those of them that needed it; emptied at every run. */
    private final List<Robot> group = new ArrayList<>();
    private final List<Robot> active = new ArrayList<>();
    private TaskHandle queued = TaskHandle.NONE;
    private double queuedTime = Double.NaN;

    /**
     * @param scheduler    queues the motion task
     * @param interval     seconds between a moving robot's evaluations (the modelling interval)
     * @param plan         the floor plan, for the sensors
     * @param surroundings what is near each robot
     * @param changed      told the simulated time after every run of the task
     */
    MotionStepper(Scheduler scheduler, double interval, RsPlan plan, Surroundings surroundings, DoubleConsumer changed) {
        this.scheduler = scheduler;
        this.interval = interval;
        this.plan = plan;
        this.surroundings = surroundings;
        this.contacts = new RobotContacts(surroundings);
        this.changed = changed;
    }

    /** The robot is evaluated at {@code time}, or earlier if it already is due earlier. */
    void evaluateBy(Robot r, double time) {
        if (due.isDue(r) && due.dueTime(r) <= time) {
            return;
        }
        due.put(r, time);
        requeue();
    }

    /**
     * A request for the robot: a robot at rest is evaluated at {@code time}; one already due keeps its
     * time (a moving robot starts the new motion at its next step, as in RP1 0.60).
     */
    void wake(Robot r, double time) {
        if (!due.isDue(r)) {
            evaluateBy(r, time);
        }
    }

    /** The robot leaves: no more evaluations. */
    void forget(Robot r) {
        if (due.isDue(r)) {
            due.remove(r);
            requeue();
        }
    }

    /** Keeps the task queued at the earliest evaluation due. */
    private void requeue() {
        if (due.isEmpty()) {
            queued.cancel();
            return;
        }
        double first = due.first();
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
        group.clear();
        active.clear();
        due.takeDueBy(time, group);
        for (Robot r : group) {
            if (r.needsProcessing()) {
                active.add(r);
            }
        }
        for (Robot r : active) {
            r.advance(time);
            if (r.hasPendingRequest()) {
                r.startPendingMotion(time, surroundings.wallsForMotion(r, r.motionToMake()));
                contacts.motionStarted(r, runs);
                // Filed where the new motion can take it before any contact search looks it up.
                surroundings.file(r, time, interval);
            }
        }
        if (surroundings.robotsCanMeet()) {
            contacts.resolve(active, time, time + interval + RobotContacts.LOOK_AHEAD, runs, this);
        }
        for (Robot r : active) {
            r.sense(time, plan, surroundings.obstaclesForSensors(r, time));
            double next = r.finish(time, interval);
            surroundings.file(r, time, interval);
            if (!Double.isNaN(next)) {
                evaluateBy(r, next);
            }
        }
        for (Robot r : group) {
            double next = contacts.pressTouched(r, time);
            if (!Double.isNaN(next) && !r.isMoving()) {
                evaluateBy(r, next);
            }
        }
        requeue();
        // Not kept past the run: a robot that leaves is not held in the lists until the next one.
        group.clear();
        active.clear();
        changed.accept(time);
    }
}
