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

    /** The placement event answering a request for {@code requested} (never null: "" for none), stamped {@code time}. */
    RsPlacementEvent find(Robot r, String requested, double time) {
        if (plan.getObjectCount() == 0) {
            return invalid(time, "");
        }
        if (requested.equals("$random")) {
            return randomPose(r, time);
        }
        if (requested.isEmpty()) {
            return randomPlacement(r, time);
        }
        for (RsPlacement p : plan.getPlacementArray()) {
            if (p.getName().equals(requested)) {
                return clear(r, p.x, p.y, p.orientation, time)
                        ? new RsPlacementEvent(time, true, p.getName(), p.x, p.y, p.orientation)
                        : invalid(time, requested);
            }
        }
        return invalid(time, requested);
    }

    private RsPlacementEvent randomPose(Robot r, double time) {
        RsRectangle b = plan.getBounds();
        for (int i = 0; i < RANDOM_PLACEMENT_ATTEMPTS; i++) {
            double x = b.x + random.nextDouble() * b.width;
            double y = b.y + random.nextDouble() * b.height;
            double theta = random.nextDouble() * 2.0 * Math.PI;
            if (clear(r, x, y, theta, time)) {
                return new RsPlacementEvent(time, true, "$random", x, y, theta);
            }
        }
        return invalid(time, "$random");
    }

    private RsPlacementEvent randomPlacement(Robot r, double time) {
        List<RsPlacement> candidates = new ArrayList<>();
        Collections.addAll(candidates, plan.getPlacementArray());
        while (!candidates.isEmpty()) {
            RsPlacement p = candidates.remove(random.nextInt(candidates.size()));
            if (clear(r, p.x, p.y, p.orientation, time)) {
                return new RsPlacementEvent(time, true, p.getName(), p.x, p.y, p.orientation);
            }
        }
        return invalid(time, "");
    }

    private static RsPlacementEvent invalid(double time, String name) {
        return new RsPlacementEvent(time, false, name, 0.0, 0.0, 0.0);
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
