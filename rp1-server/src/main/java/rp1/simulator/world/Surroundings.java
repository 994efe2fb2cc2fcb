package rp1.simulator.world;

import static rp1.rossum.wire.MotionLimits.NULL_LIMIT;
import static rp1.rossum.wire.MotionLimits.STRAIGHT_LIMIT;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;
import rp1.rossum.request.RsMotionRequest;

/**
 * The broad phase: what is near a place, a box or a path, so that placements, motions, sensors and
 * contact searches look only at the walls and robots that could matter. It files the plan's walls
 * ({@link WallIndex}) and the robots on the floor ({@link RobotIndex}), and counts the robots on the
 * floor. Other robots count only if robots interact.
 */
final class Surroundings {
    /** Margin, metres, around a robot's reach when looking for what it could touch (beyond the 1e-4 m of the clear test). */
    private static final double NEAR = 0.01;
    private static final RsWall[] NO_WALLS = new RsWall[0];

    private final WallIndex walls;
    private final RobotIndex robots;
    private final boolean robotsInteract;
    /**
     * The pose of a robot a sensor might see, written anew for each (its walls are kept by a copy of
     * the pose they were made at).
     */
    private final RsTransform seenPose = new RsTransform();
    private int onFloor;

    /**
     * @param walls          the plan's walls and obstacles
     * @param area           the plan's bounds, over which robots are filed
     * @param robotsInteract whether robots collide with, sense and block the placement of one another
     */
    Surroundings(RsWall[] walls, RsRectangle area, boolean robotsInteract) {
        this.walls = new WallIndex(walls);
        this.robots = new RobotIndex(area);
        this.robotsInteract = robotsInteract;
    }

    /** The robot is now on the floor, at its pose at {@code time}. */
    void enter(Robot r, double time) {
        onFloor++;
        robots.put(r, time, 0.0);
    }

    /** The robot is off the floor. */
    void leave(Robot r) {
        onFloor--;
        robots.remove(r);
    }

    /** How many robots are on the floor. */
    int onFloor() {
        return onFloor;
    }

    /** Whether two robots could meet now: robots interact and more than one is on the floor. */
    boolean robotsCanMeet() {
        return robotsInteract && onFloor > 1;
    }

    /** Files an evaluated robot where it can be until it is evaluated again (and an interval more). */
    void file(Robot r, double time, double interval) {
        if (r.isPlaced()) {
            robots.put(r, time, r.isMoving() ? 2 * interval + RobotContacts.LOOK_AHEAD : 0.0);
        }
    }

    /** The robots on the floor other than {@code self} filed within the box [x0, x1] x [y0, y1], in joining order. */
    List<Robot> robotsNear(Robot self, double x0, double y0, double x1, double y1) {
        return robots.near(x0, y0, x1, y1, self, null);
    }

    /**
     * What the robot, standing at (x, y), could overlap or come within 1e-4 m of: the walls near it
     * and (if robots interact) the shapes, as walls, of the other robots on the floor near it.
     */
    RsWall[] obstaclesAround(Robot r, double x, double y, double time) {
        RsWall[] nearWalls = wallsAround(r, x, y);
        return robotsInteract
                ? withRobots(nearWalls, shapesOfRobotsNear(r, x, y, r.shapes().reach() + NEAR, time)) : nearWalls;
    }

    /** The walls the robot, standing at (x, y), could overlap or come within 1e-4 m of. */
    RsWall[] wallsAround(Robot r, double x, double y) {
        double reach = r.shapes().reach() + NEAR;
        return walls.near(x - reach, y - reach, x + reach, y + reach);
    }

    /** Whether robots collide with, sense and block the placement of one another. */
    boolean robotsInteract() {
        return robotsInteract;
    }

    /**
     * The shapes, as walls, of the other robots on the floor whose reach comes within {@code reach} of
     * (x, y), in joining order (the index holds only robots on the floor).
     */
    private List<RsWall[]> shapesOfRobotsNear(Robot self, double x, double y, double reach, double time) {
        List<RsWall[]> near = new ArrayList<>();
        for (Robot o : robots.near(x - reach, y - reach, x + reach, y + reach, self, null)) {
            RsTransform p = o.poseAt(time);
            if (Math.hypot(p.m13 - x, p.m23 - y) <= reach + o.shapes().reach()) {
                near.add(o.obstaclesAt(p));
            }
        }
        return near;
    }

    /**
     * What blocks the robot's range and target sensors at {@code time}: the walls near what the sensors
     * look at from where the robot is (its rays, its target sensors' discs), plus the other robots on
     * the floor that the sensors could see. A robot without such sensors needs none. A wall that crosses
     * no ray and hides no target changes no reading, and the walls kept are in the order they were.
     */
    RsWall[] obstaclesForSensors(Robot r, double time) {
        if (!r.hasWallSensors()) {
            return NO_WALLS;
        }
        RsTransform p = r.pose();
        double[] box = r.sightBox(p);
        double x0 = box[0];
        double y0 = box[1];
        double x1 = box[2];
        double y1 = box[3];
        RsWall[] nearWalls = walls.near(x0, y0, x1, y1);
        if (!robotsCanMeet()) {
            return nearWalls;
        }
        List<RsWall[]> seen = new ArrayList<>();
        for (Robot o : robots.near(x0, y0, x1, y1, r, r.sightFrom(p))) {
            RsTransform b = o.poseAt(time, seenPose);
            if (r.mightSee(p, o, b)) {
                seen.add(o.obstaclesAt(b));
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
            return walls.alongSegment(p.m13, p.m23, p.m13 + d * Math.cos(heading), p.m23 + d * Math.sin(heading), reach);
        }
        double rho = Math.abs(v / w) * Math.signum(w);
        double cx = p.m13 - rho * Math.sin(theta);
        double cy = p.m23 + rho * Math.cos(theta);
        double radius = Math.abs(rho) + reach;
        return walls.near(cx - radius, cy - radius, cx + radius, cy + radius);
    }

    /** The walls followed by the other robots' shapes (as walls), in order. */
    private static RsWall[] withRobots(RsWall[] walls, List<RsWall[]> others) {
        int n = walls.length;
        for (RsWall[] o : others) {
            n += o.length;
        }
        RsWall[] all = Arrays.copyOf(walls, n);
        int at = walls.length;
        for (RsWall[] o : others) {
            System.arraycopy(o, 0, all, at, o.length);
            at += o.length;
        }
        return all;
    }
}
