package rp1.simulator.snapshot;

import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;
import rp1.simulator.Simulation;
import rp1.simulator.world.PaintTrail;
import rp1.simulator.world.Robot;
import rp1.simulator.world.TrailSegment;
import rp1.simulator.world.World;

/**
 * The world at one simulation time, as an observer may show it: the plan (static) with which targets
 * are selected, every robot, and every paint trail (those of departed robots too). Immutable; safe
 * to hand to any thread.
 *
 * @param plan           the floor plan (its objects never change; only target selection does)
 * @param simTime        the simulation time of the snapshot, seconds
 * @param targetSelected per target of the plan, in {@link RsPlan#getTargetArray()} order, whether it
 *                       was selected (deselected targets are neither sensed nor drawn)
 * @param robots         the robots in joining order, placed or not
 * @param trails         the paint-trail segments, oldest robot first
 */
public record WorldSnapshot(RsPlan plan, double simTime, List<Boolean> targetSelected, List<RobotSnapshot> robots,
                            List<TrailSnapshot> trails) {

    /** Copies the lists. */
    public WorldSnapshot {
        targetSelected = List.copyOf(targetSelected);
        robots = List.copyOf(robots);
        trails = List.copyOf(trails);
    }

    /**
     * The world now. Call on the thread running the simulation's tasks: robots move, parts turn hot,
     * trails grow and targets are selected only there (docs/architecture.md).
     */
    public static WorldSnapshot of(World world, double simTime) {
        List<RobotSnapshot> robots = new ArrayList<>();
        List<TrailSnapshot> trails = new ArrayList<>();
        addTrails(trails, world.getDepartedTrails());
        for (Robot r : world.getRobots()) {
            robots.add(RobotSnapshot.of(r));
            addTrails(trails, r.getTrails());
        }
        return new WorldSnapshot(world.getPlan(), simTime, targetSelection(world.getPlan()), robots, trails);
    }

    /** The simulation's world now, as {@link #of(World, double)}; for observers outside the core (the view). */
    public static WorldSnapshot of(Simulation simulation, double simTime) {
        return of(simulation.getWorld(), simTime);
    }

    /**
     * The simulation's world at the time its scheduler reached: the picture at exit, taken once the
     * scheduler has stopped.
     */
    public static WorldSnapshot atRecordedTime(Simulation simulation) {
        return of(simulation.getWorld(), simulation.getScheduler().recordedTime());
    }

    /**
     * The plan alone, before anything happened: no robots, no trails, time 0. Called before the run
     * starts (the first picture a window shows) or for a plan no simulation uses.
     */
    public static WorldSnapshot planOnly(RsPlan plan) {
        return new WorldSnapshot(plan, 0.0, targetSelection(plan), List.of(), List.of());
    }

    private static List<Boolean> targetSelection(RsPlan plan) {
        List<Boolean> selected = new ArrayList<>();
        for (RsTarget t : plan.getTargetArray()) {
            selected.add(t.getSelected());
        }
        return selected;
    }

    private static void addTrails(List<TrailSnapshot> out, List<PaintTrail> trails) {
        for (PaintTrail t : trails) {
            for (TrailSegment s : t.getSegments()) {
                out.add(TrailSnapshot.of(s));
            }
        }
    }

    /** Whether target number {@code index} (in plan order among the targets) was selected. */
    public boolean isTargetSelected(int index) {
        return targetSelected.get(index);
    }

    /** The robots on the floor, in joining order. */
    public List<RobotSnapshot> placedRobots() {
        List<RobotSnapshot> placed = new ArrayList<>();
        for (RobotSnapshot r : robots) {
            if (r.placed()) {
                placed.add(r);
            }
        }
        return placed;
    }
}
