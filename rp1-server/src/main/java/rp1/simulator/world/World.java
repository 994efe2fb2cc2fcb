package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.IntConsumer;

import rp1.rossum.RsBody;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsTargetSelectionRequest;
import rp1.simulator.scheduler.Scheduler;

/**
 * The simulated world: the floor plan and the robots in it. Robots join when their client sends a
 * body, in that order; every client with a body is a robot here, and robots collide with each other
 * and see each other with their range sensors (RP1 0.60 let them pass through each other unseen).
 *
 * <p>All changes happen on the thread running the simulation's tasks: in tasks, or in client
 * requests applied at the boundaries between tasks (see {@link rp1.simulator.scheduler.Scheduler}).
 * The robot list may be read from other threads (it is copy-on-write); a view takes snapshots instead.
 */
public final class World {
    /** Random poses ("$random") are drawn this many times before the placement fails. */
    static final int RANDOM_PLACEMENT_ATTEMPTS = 50;

    private final RsPlan plan;
    private final RsWall[] walls;
    private final Random random;
    private final MotionStepper stepper;
    private final List<Robot> robots = new CopyOnWriteArrayList<>();
    private final List<WorldListener> listeners = new CopyOnWriteArrayList<>();
    private final List<PaintTrail> departedTrails = new CopyOnWriteArrayList<>();
    private final boolean robotsInteract;
    private IntConsumer placementListener = n -> { };
    private int joined;
    private int placedCount;

    /**
     * @param plan           the floor plan
     * @param scheduler      the simulation's scheduler
     * @param interval       seconds between motion evaluations (the modelling interval)
     * @param random         the simulation's one seeded random source
     * @param robotsInteract whether robots collide with, sense and block the placement of one another
     */
    public World(RsPlan plan, Scheduler scheduler, double interval, Random random, boolean robotsInteract) {
        this.plan = plan;
        this.walls = plan.getWallArray();
        this.random = random;
        this.robotsInteract = robotsInteract;
        this.stepper = new MotionStepper(this, scheduler, interval);
        plan.setRandom(random);
    }

    /** A world whose robots meet each other. */
    public World(RsPlan plan, Scheduler scheduler, double interval, Random random) {
        this(plan, scheduler, interval, random, true);
    }

    /** Told the number of robots on the floor whenever it changes. */
    public void setPlacementListener(IntConsumer listener) {
        placementListener = listener;
    }

    /** Whether robots collide with, sense and block the placement of one another. */
    public boolean robotsInteract() {
        return robotsInteract;
    }

    /** The number of robots on the floor. */
    public int getPlacedCount() {
        return placedCount;
    }

    private void setPlaced(Robot r, boolean placed) {
        if (r.isPlaced() == placed) {
            return;
        }
        if (placed) {
            r.markPlaced();
            placedCount++;
        } else {
            r.markUnplaced();
            placedCount--;
        }
        placementListener.accept(placedCount);
    }

    /** A placement request arrived: the robot is off the floor until the placement succeeds. */
    public void unplace(Robot r) {
        setPlaced(r, false);
    }

    public RsPlan getPlan() {
        return plan;
    }

    /** The plan's walls and obstacles. */
    RsWall[] getWalls() {
        return walls;
    }

    /** The robots in the order they joined. */
    public List<Robot> getRobots() {
        return Collections.unmodifiableList(robots);
    }

    /** The robots currently on the floor, in joining order. */
    public List<Robot> getPlacedRobots() {
        List<Robot> placed = new ArrayList<>();
        for (Robot r : robots) {
            if (r.isPlaced()) {
                placed.add(r);
            }
        }
        return placed;
    }

    /** A client's body joins the world as an unplaced robot. */
    public Robot addRobot(RsBody body, EventSink events) {
        Robot r = new Robot(++joined, body, events);
        robots.add(r);
        return r;
    }

    /**
     * A robot leaves (its client went away); its paint trails stay on the floor, and the motion task
     * goes when no robot is left.
     */
    public void removeRobot(Robot r) {
        if (robots.remove(r)) {
            departedTrails.addAll(r.getTrails());
        }
        setPlaced(r, false);
        if (robots.isEmpty()) {
            stepper.cancel();
        }
        changed(Double.NaN);
    }

    /** A motion request for a placed robot: it starts at the robot's next evaluation. */
    public void requestMotion(Robot r, RsMotionRequest request, double time) {
        if (!r.isPlaced() || request == null) {
            return;
        }
        r.setPendingRequest(request);
        stepper.wake(time);
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
     */
    public void place(Robot r, String name, double time) {
        String requested = name == null ? "" : name;
        RsPlacementEvent event = findPlacement(r, requested, time);
        if (event.valid) {
            r.place(time, event.x, event.y, event.orientation);
            setPlaced(r, true);
            stepper.wake(time);
        } else {
            setPlaced(r, false);
        }
        r.events().send(event);
        changed(time);
    }

    private RsPlacementEvent findPlacement(Robot r, String requested, double time) {
        if (plan.getObjectCount() == 0) {
            return invalid(time, "");
        }
        RsWall[] obstacles = placementObstacles(r);
        if (requested.equals("$random")) {
            return randomPose(r, obstacles, time);
        }
        if (requested.isEmpty()) {
            return randomPlacement(r, obstacles, time);
        }
        for (RsPlacement p : plan.getPlacementArray()) {
            if (p.getName().equals(requested)) {
                return clear(r, obstacles, p.x, p.y, p.orientation)
                        ? new RsPlacementEvent(time, true, p.getName(), p.x, p.y, p.orientation)
                        : invalid(time, requested);
            }
        }
        return invalid(time, requested);
    }

    private RsPlacementEvent randomPose(Robot r, RsWall[] obstacles, double time) {
        RsRectangle b = plan.getBounds();
        for (int i = 0; i < RANDOM_PLACEMENT_ATTEMPTS; i++) {
            double x = b.x + random.nextDouble() * b.width;
            double y = b.y + random.nextDouble() * b.height;
            double theta = random.nextDouble() * 2.0 * Math.PI;
            if (clear(r, obstacles, x, y, theta)) {
                return new RsPlacementEvent(time, true, "$random", x, y, theta);
            }
        }
        return invalid(time, "$random");
    }

    private RsPlacementEvent randomPlacement(Robot r, RsWall[] obstacles, double time) {
        List<RsPlacement> candidates = new ArrayList<>();
        Collections.addAll(candidates, plan.getPlacementArray());
        while (!candidates.isEmpty()) {
            RsPlacement p = candidates.remove(random.nextInt(candidates.size()));
            if (clear(r, obstacles, p.x, p.y, p.orientation)) {
                return new RsPlacementEvent(time, true, p.getName(), p.x, p.y, p.orientation);
            }
        }
        return invalid(time, "");
    }

    private static RsPlacementEvent invalid(double time, String name) {
        return new RsPlacementEvent(time, false, name, 0.0, 0.0, 0.0);
    }

    private static boolean clear(Robot r, RsWall[] obstacles, double x, double y, double theta) {
        return !r.getBody().checkForOverlap(obstacles, new RsTransform(theta, x, y));
    }

    /** Walls plus every other robot on the floor (if robots interact). */
    private RsWall[] placementObstacles(Robot r) {
        return robotsInteract ? withRobots(r, getPlacedRobots()) : walls;
    }

    /**
     * What blocks the robot's range and target sensors: the walls, plus the other robots on the floor
     * within the sensors' reach.
     */
    RsWall[] obstaclesFor(Robot r, List<Robot> placed) {
        if (!robotsInteract || !r.hasWallSensors() || placed.size() < 2) {
            return walls;
        }
        // Only robots within the sensors' reach can change a reading; with many robots, looking at
        // all of them from every robot at every step made the world quadratic.
        List<Robot> seen = new ArrayList<>();
        for (Robot o : placed) {
            if (o != r && r.canSee(o)) {
                seen.add(o);
            }
        }
        return seen.isEmpty() ? walls : withRobots(r, seen);
    }

    private RsWall[] withRobots(Robot self, List<Robot> others) {
        List<RsWall> all = new ArrayList<>(walls.length + 4 * others.size());
        Collections.addAll(all, walls);
        for (Robot o : others) {
            if (o != self && o.isPlaced()) {
                Collections.addAll(all, o.asObstacles());
            }
        }
        return all.toArray(new RsWall[0]);
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
