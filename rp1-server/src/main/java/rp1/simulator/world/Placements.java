package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsPlacementEvent;

/**
 * Where a placement request puts a robot (docs/behavior.md section 7): by name, at a random one of the
 * plan's placements (null or empty name), or at a random free pose ("$random"), each only if the pose
 * is clear. Random choices draw from the world's one seeded source.
 */
final class Placements {
    /** Random poses ("$random") are drawn this many times before the placement fails. */
    static final int RANDOM_PLACEMENT_ATTEMPTS = 50;

    private final RsPlan plan;
    private final Random random;
    private final Surroundings surroundings;

    Placements(RsPlan plan, Random random, Surroundings surroundings) {
        this.plan = plan;
        this.random = random;
        this.surroundings = surroundings;
    }

    /** The answer to a placement request, and why it was refused (null if it was not). */
    record Placement(RsPlacementEvent event, String refusal) {
        static Placement at(double time, String name, double x, double y, double orientation) {
            return new Placement(new RsPlacementEvent(time, true, name, x, y, orientation), null);
        }

        static Placement refused(double time, String name, String why) {
            return new Placement(new RsPlacementEvent(time, false, name, 0.0, 0.0, 0.0), why);
        }
    }

    /** The answer to a request for {@code requested} (never null: "" for none), stamped {@code time}. */
    Placement find(Robot r, String requested, double time) {
        if (plan.getObjectCount() == 0) {
            return Placement.refused(time, "", "the floor plan is empty");
        }
        if (requested.equals("$random")) {
            return randomPose(r, time);
        }
        if (requested.isEmpty()) {
            return randomPlacement(r, time);
        }
        // Names are unique in a plan, which keeps its objects by name: placing ten thousand robots by
        // name, each scanning a copy of the plan's placements, took seconds.
        if (plan.getObjectByName(requested) instanceof RsPlacement p) {
            String blocked = blockedBy(r, p.x, p.y, p.orientation, time);
            return blocked == null ? Placement.at(time, p.getName(), p.x, p.y, p.orientation)
                    : Placement.refused(time, requested, blocked + " is in the way");
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
        return surroundings.robotsInteract() && clearOfWalls(r, x, y, theta) ? "another robot" : "a wall";
    }

    /** Whether the robot at (x, y, theta) overlaps no wall, whatever the other robots do. */
    private boolean clearOfWalls(Robot r, double x, double y, double theta) {
        return !r.getBody().checkForOverlap(surroundings.wallsAround(r, x, y), new RsTransform(theta, x, y));
    }

    /**
     * Whether the robot can stand at (x, y, theta): no wall, and (if robots interact) no other robot on
     * the floor, overlaps or comes within 1e-4 m of it. Only what is near the pose is looked at.
     */
    private boolean clear(Robot r, double x, double y, double theta, double time) {
        return r.shapes().isEmpty()
                || !r.getBody().checkForOverlap(surroundings.obstaclesAround(r, x, y, time), new RsTransform(theta, x, y));
    }
}
