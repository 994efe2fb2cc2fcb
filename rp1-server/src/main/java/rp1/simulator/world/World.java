package rp1.simulator.world;

import static rp1.rossum.wire.MotionLimits.NULL_LIMIT;
import static rp1.rossum.wire.MotionLimits.STRAIGHT_LIMIT;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
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
 * body, in that order; every client with a body is a robot here. Unless the world is made with
 * {@code robotsInteract} false, robots collide with each other, see each other with their range
 * sensors and keep each other from being placed on top of one another (RP1 0.60 let them pass through
 * each other unseen, as they still do with {@code robotsInteract} false).
 *
 * <p>All changes happen on the thread running the simulation's tasks: in tasks, or in client
 * requests applied at the boundaries between tasks (see {@link rp1.simulator.scheduler.Scheduler}).
 * The robot list may be read from other threads (it is copy-on-write); a view takes snapshots instead.
 */
public final class World {
    /** Random poses ("$random") are drawn this many times before the placement fails. */
    static final int RANDOM_PLACEMENT_ATTEMPTS = 50;
    /** Margin, metres, around a robot's reach when looking for what it could touch (beyond the 1e-4 m of the clear test). */
    private static final double NEAR = 0.01;
    private static final RsWall[] NO_WALLS = new RsWall[0];

    private final RsPlan plan;
    private final WallIndex wallIndex;
    private final RobotIndex robotIndex;
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
        this.wallIndex = new WallIndex(plan.getWallArray());
        this.robotIndex = new RobotIndex(plan.getBounds());
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

    private void setPlaced(Robot r, boolean placed) {
        if (r.isPlaced() == placed) {
            return;
        }
        if (placed) {
            r.markPlaced();
            placedCount++;
            robotIndex.put(r, r.motion().time, 0.0);
        } else {
            r.markUnplaced();
            placedCount--;
            robotIndex.remove(r);
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

    /** The robots in the order they joined. */
    public List<Robot> getRobots() {
        return Collections.unmodifiableList(robots);
    }

    /** A client's body joins the world as an unplaced robot. */
    public Robot addRobot(RsBody body, EventSink events) {
        Robot r = new Robot(++joined, body, events);
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
        Placement found = findPlacement(r, requested, time);
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

    /** The answer to a placement request, and why it was refused (null if it was not). */
    private record Placement(RsPlacementEvent event, String refusal) {
        static Placement at(double time, String name, double x, double y, double orientation) {
            return new Placement(new RsPlacementEvent(time, true, name, x, y, orientation), null);
        }

        static Placement refused(double time, String name, String why) {
            return new Placement(new RsPlacementEvent(time, false, name, 0.0, 0.0, 0.0), why);
        }
    }

    private Placement findPlacement(Robot r, String requested, double time) {
        if (plan.getObjectCount() == 0) {
            return Placement.refused(time, "", "the floor plan is empty");
        }
        if (requested.equals("$random")) {
            return randomPose(r, time);
        }
        if (requested.isEmpty()) {
            return randomPlacement(r, time);
        }
        for (RsPlacement p : plan.getPlacementArray()) {
            if (p.getName().equals(requested)) {
                String blocked = blockedBy(r, p.x, p.y, p.orientation, time);
                return blocked == null ? Placement.at(time, p.getName(), p.x, p.y, p.orientation)
                        : Placement.refused(time, requested, blocked + " is in the way");
            }
        }
        return Placement.refused(time, requested, "the floor plan has no placement of that name");
    }

    private Placement randomPose(Robot r, double time) {
        RsRectangle b = plan.getBounds();
        for (int i = 0; i < RANDOM_PLACEMENT_ATTEMPTS; i++) {
            double x = b.x + random.nextDouble() * b.width;
            double y = b.y + random.nextDouble() * b.height;
            double theta = random.nextDouble() * 2.0 * Math.PI;
            if (clear(r, x, y, theta, time)) {
                return Placement.at(time, "$random", x, y, theta);
            }
        }
        return Placement.refused(time, "$random", "no free pose found in " + RANDOM_PLACEMENT_ATTEMPTS + " tries");
    }

    private Placement randomPlacement(Robot r, double time) {
        List<RsPlacement> candidates = new ArrayList<>();
        Collections.addAll(candidates, plan.getPlacementArray());
        boolean any = !candidates.isEmpty();
        while (!candidates.isEmpty()) {
            RsPlacement p = candidates.remove(random.nextInt(candidates.size()));
            if (clear(r, p.x, p.y, p.orientation, time)) {
                return Placement.at(time, p.getName(), p.x, p.y, p.orientation);
            }
        }
        return Placement.refused(time, "", any ? "every placement of the floor plan is taken or blocked"
                : "the floor plan has no placements");
    }

    /** What keeps the robot from standing at (x, y, theta): null if nothing, else "a wall" or "another robot". */
    private String blockedBy(Robot r, double x, double y, double theta, double time) {
        if (clear(r, x, y, theta, time)) {
            return null;
        }
        return robotsInteract && clearOfWalls(r, x, y, theta) ? "another robot" : "a wall";
    }

    /**
     * Whether the robot can stand at (x, y, theta): no wall, and (if robots interact) no other robot on
     * the floor, overlaps or comes within 1e-4 m of it. Only what is near the pose is looked at.
     */
    private boolean clear(Robot r, double x, double y, double theta, double time) {
        if (r.shapes().isEmpty()) {
            return true;
        }
        double reach = r.shapes().reach() + NEAR;
        RsWall[] nearWalls = wallIndex.near(x - reach, y - reach, x + reach, y + reach);
        RsWall[] obstacles = robotsInteract ? withRobots(nearWalls, shapesOfRobotsNear(r, x, y, reach, time)) : nearWalls;
        return !r.getBody().checkForOverlap(obstacles, new RsTransform(theta, x, y));
    }

    /** Whether the robot at (x, y, theta) overlaps no wall, whatever the other robots do. */
    private boolean clearOfWalls(Robot r, double x, double y, double theta) {
        double reach = r.shapes().reach() + NEAR;
        RsWall[] nearWalls = wallIndex.near(x - reach, y - reach, x + reach, y + reach);
        return !r.getBody().checkForOverlap(nearWalls, new RsTransform(theta, x, y));
    }

    /**
     * The shapes, as walls, of the other robots on the floor whose reach comes within {@code reach} of
     * (x, y), in joining order (the index holds only robots on the floor).
     */
    private List<RsWall[]> shapesOfRobotsNear(Robot self, double x, double y, double reach, double time) {
        List<RsWall[]> near = new ArrayList<>();
        for (Robot o : robotIndex.near(x - reach, y - reach, x + reach, y + reach)) {
            if (o != self) {
                RsTransform p = o.poseAt(time);
                if (Math.hypot(p.m13 - x, p.m23 - y) <= reach + o.shapes().reach()) {
                    near.add(o.obstaclesAt(p));
                }
            }
        }
        return near;
    }

    /**
     * At a motion evaluation: searches the coming interval [from, to] for contacts between the robots
     * evaluated and the robots near them (if robots interact).
     */
    void searchContacts(List<Robot> evaluated, double from, double to, long run) {
        if (robotsInteract && placedCount > 1) {
            RobotContacts.resolve(evaluated, robotIndex, from, to, run, stepper);
        }
    }

    /** Files an evaluated robot in the index where it can be until it is evaluated again (and an interval more). */
    void indexRobot(Robot r, double time, double interval) {
        if (r.isPlaced()) {
            robotIndex.put(r, time, r.isMoving() ? 2 * interval + RobotContacts.LOOK_AHEAD : 0.0);
        }
    }

    /**
     * What blocks the robot's range and target sensors at {@code time}: the walls within the sensors'
     * reach, plus the other robots on the floor within it. A robot without such sensors needs none.
     */
    RsWall[] obstaclesFor(Robot r, double time) {
        if (!r.hasWallSensors()) {
            return NO_WALLS;
        }
        RsTransform p = r.pose();
        double reach = r.sensorReach();
        double x0 = p.m13 - reach;
        double y0 = p.m23 - reach;
        double x1 = p.m13 + reach;
        double y1 = p.m23 + reach;
        RsWall[] nearWalls = wallIndex.near(x0, y0, x1, y1);
        if (!robotsInteract || placedCount < 2) {
            return nearWalls;
        }
        List<RsWall[]> seen = new ArrayList<>();
        for (Robot o : robotIndex.near(x0, y0, x1, y1)) {
            if (o != r) {
                RsTransform b = o.poseAt(time);
                if (r.mightSee(p, o, b)) {
                    seen.add(o.obstaclesAt(b));
                }
            }
        }
        return seen.isEmpty() ? nearWalls : withRobots(nearWalls, seen);
    }

    /**
     * The walls a motion requested from the robot's current pose could meet (docs/behavior.md section
     * 5.2): along the line it would drive, or within the circle of an arc; none for a null motion.
     */
    RsWall[] wallsForMotion(Robot r, RsMotionRequest q) {
        double v = q.linearVelocity;
        double w = q.rotationalVelocity;
        if (q.duration < NULL_LIMIT || (Math.abs(v) < NULL_LIMIT && Math.abs(w) < NULL_LIMIT)) {
            return NO_WALLS;
        }
        RsTransform p = r.pose();
        double theta = p.getTheta();
        double reach = r.shapes().reach() + NEAR;
        if (Math.abs(w) < STRAIGHT_LIMIT) {
            double d = Math.abs(v * q.duration);
            double heading = v < 0 ? theta + Math.PI : theta;
            return wallIndex.alongSegment(p.m13, p.m23, p.m13 + d * Math.cos(heading), p.m23 + d * Math.sin(heading), reach);
        }
        double rho = Math.abs(v / w) * Math.signum(w);
        double cx = p.m13 - rho * Math.sin(theta);
        double cy = p.m23 + rho * Math.cos(theta);
        double radius = Math.abs(rho) + reach;
        return wallIndex.near(cx - radius, cy - radius, cx + radius, cy + radius);
    }

    /** The walls followed by the other robots' shapes (as walls), in order. */
    private static RsWall[] withRobots(RsWall[] walls, List<RsWall[]> others) {
        List<RsWall> all = new ArrayList<>(walls.length + 4 * others.size());
        Collections.addAll(all, walls);
        for (RsWall[] o : others) {
            Collections.addAll(all, o);
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
