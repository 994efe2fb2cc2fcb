package rp1.simulator.world;

import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.IntConsumer;

import rp1.rossum.RsBody;
import rp1.rossum.RsPlan;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.simulator.noise.Noise;
import rp1.simulator.scheduler.Scheduler;

/**
 * The simulated world: the floor plan and the robots in it. Robots join when their client sends a
 * body, in that order; every client with a body is a robot here. Unless the world is made with
 * {@code robotsInteract} false, robots collide with each other, see each other with their range
 * sensors and keep each other from being placed on top of one another (RP1 0.60 let them pass through
 * each other unseen, as they still do with {@code robotsInteract} false).
 *
 * <p>All changes happen on the thread running the simulation's tasks: in tasks, or in client
 * requests applied at the boundaries between tasks (see {@link rp1.simulator.scheduler.Scheduler}).
 * The robot list may be read from other threads (it is copy-on-write); a view takes snapshots instead.
 *
 * <p>The world applies what clients ask for and tells its listeners; the work is done by its parts:
 * {@link Placements} (where a robot may stand), {@link MotionStepper} (motion evaluation, with
 * {@link RobotContacts}) and {@link Surroundings} (what is near a place, for all of them).
 */
public final class World {
    private final RsPlan plan;
    private final Surroundings surroundings;
    private final Placements placements;
    private final MotionStepper stepper;
    private final List<Robot> robots = new CopyOnWriteArrayList<>();
    private final List<WorldListener> listeners = new CopyOnWriteArrayList<>();
    private final List<PaintTrail> departedTrails = new CopyOnWriteArrayList<>();
    private IntConsumer placementListener = n -> { };
    private int joined;
    /** The robots' outlines, one copy per design. */
    private final OutlineSources outlineSources = new OutlineSources();
    /** The run's noise, which gives each robot that joins its own. */
    private Noise noise = Noise.OFF;

    /**
     * @param plan           the floor plan
     * @param scheduler      the simulation's scheduler
     * @param interval       seconds between motion evaluations (the modelling interval)
     * @param random         the simulation's one seeded random source
     * @param robotsInteract whether robots collide with, sense and block the placement of one another
     */
    public World(RsPlan plan, Scheduler scheduler, double interval, Random random, boolean robotsInteract) {
        this.plan = plan;
        this.surroundings = new Surroundings(plan.getWallArray(), plan.getBounds(), robotsInteract);
        this.placements = new Placements(plan, random, surroundings);
        this.stepper = new MotionStepper(scheduler, interval, plan, surroundings, this::changed);
        plan.setRandom(random);
    }

    /** A world whose robots meet each other. */
    public World(RsPlan plan, Scheduler scheduler, double interval, Random random) {
        this(plan, scheduler, interval, random, true);
    }

    /**
     * Sensors and motion of the robots that join from now on are as noisy as {@code noise} says
     * (default {@link Noise#OFF}: exact, as in RP1 0.60).
     */
    public void setNoise(Noise noise) {
        this.noise = noise;
    }

    /** Told the number of robots on the floor whenever it changes. */
    public void setPlacementListener(IntConsumer listener) {
        placementListener = listener;
    }

    private void setPlaced(Robot r, boolean placed) {
        if (r.isPlaced() == placed) {
            return;
        }
        if (placed) {
            r.markPlaced();
            surroundings.enter(r, r.motion().time);
        } else {
            r.markUnplaced();
            surroundings.leave(r);
        }
        placementListener.accept(surroundings.onFloor());
    }

    /** A placement request arrived: the robot is off the floor until the placement succeeds. */
    public void unplace(Robot r) {
        setPlaced(r, false);
    }

    public RsPlan getPlan() {
        return plan;
    }

    /** The robots in the order they joined. */
    public List<Robot> getRobots() {
        return Collections.unmodifiableList(robots);
    }

    /** A client's body joins the world as an unplaced robot. */
    public Robot addRobot(RsBody body, EventSink events) {
        joined++;
        Robot r = new Robot(joined, body, events, noise.forRobot(joined), outlineSources);
        robots.add(r);
        return r;
    }

    /**
     * A robot leaves (its client went away); its paint trails stay on the floor, and it is not
     * evaluated again (the motion task goes when no robot is due).
     */
    public void removeRobot(Robot r) {
        if (robots.remove(r)) {
            departedTrails.addAll(r.getTrails());
        }
        setPlaced(r, false);
        stepper.forget(r);
        changed(Double.NaN);
    }

    /** A motion request for a placed robot: it starts at the robot's next evaluation. */
    public void requestMotion(Robot r, RsMotionRequest request, double time) {
        if (!r.isPlaced() || request == null) {
            return;
        }
        r.setPendingRequest(request);
        stepper.wake(r, time);
    }

    /** A halt request: the waiting request is dropped and a motion under way stops now. */
    public void halt(Robot r, double time) {
        r.halt(time);
    }

    /**
     * A placement request (docs/behavior.md section 7): by name, at a random one of the plan's placements
     * (null or empty name), or at a random free pose ("$random"). A pose is clear if the robot
     * overlaps no wall and no other robot on the floor. Answers with a placement event. The motion
     * task is queued before the event goes out, so that requests the client sends in answer to it
     * always come after the evaluation of the new pose.
     *
     * @return why the placement was refused (for the server's log), or null if the robot is placed
     */
    public String place(Robot r, String name, double time) {
        String requested = name == null ? "" : name;
        Placements.Placement found = placements.find(r, requested, time);
        RsPlacementEvent event = found.event();
        if (event.valid) {
            r.place(time, event.x, event.y, event.orientation);
            setPlaced(r, true);
            stepper.evaluateBy(r, time);
        } else {
            setPlaced(r, false);
        }
        r.events().send(event);
        changed(time);
        return found.refusal();
    }

    /**
     * A target-selection request, applied at once (docs/behavior.md section 8.7): the events for the
     * targets it changed, stamped {@code time}, in plan order; random picks draw from the world's seeded
     * source.
     */
    public RsTargetSelectionEvent[] selectTargets(RsTargetSelectionRequest request, double time) {
        RsTargetSelectionEvent[] events = plan.processTargetSelectionRequest(time, request);
        changed(Double.NaN);
        return events;
    }

    /** A painter-change request for one of the robot's painters. */
    public void painterChange(Robot r, RsPainterChangeRequest request) {
        r.changePainter(request);
        changed(Double.NaN);
    }

    /** Clears every paint trail, those of departed robots too (the view's "Remove Paint Trails"). */
    public void removePaintTrails() {
        for (Robot r : robots) {
            r.eraseTrails();
        }
        departedTrails.clear();
        changed(Double.NaN);
    }

    /** The trails of robots whose clients left, which stay on the floor (behavior.md section 9). */
    public List<PaintTrail> getDepartedTrails() {
        return Collections.unmodifiableList(departedTrails);
    }

    public void addListener(WorldListener l) {
        listeners.add(l);
    }

    public void removeListener(WorldListener l) {
        listeners.remove(l);
    }

    /** Tells the listeners the picture changed ({@code simTime} NaN when not at a motion step). */
    public void changed(double simTime) {
        for (WorldListener l : listeners) {
            l.worldChanged(this, simTime);
        }
    }
}
