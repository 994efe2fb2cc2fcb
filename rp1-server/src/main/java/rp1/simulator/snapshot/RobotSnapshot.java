package rp1.simulator.snapshot;

import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsActuator;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsTransform;
import rp1.simulator.world.Robot;

/**
 * One robot at snapshot time.
 *
 * @param number the order in which it joined, from 1
 * @param label  its name, as other robots' sensors report it
 * @param placed whether it is on the floor (only placed robots are drawn)
 * @param x      position of the body origin, world metres
 * @param y      position of the body origin, world metres
 * @param theta  heading, radians
 * @param parts  the body parts in drawing order: the body's parts in order, each actuator (wheel
 *               system) followed by its sub-parts (wheels)
 * @param believed where the robot believes it is, when wheel slip makes that differ from the truth
 *               (x, y, theta; docs/behavior.md section 8.9), else null
 */
public record RobotSnapshot(int number, String label, boolean placed, double x, double y, double theta,
                            List<PartSnapshot> parts, double[] believed) {

    /** Copies the parts list and the belief. */
    public RobotSnapshot {
        parts = List.copyOf(parts);
        believed = believed == null ? null : believed.clone();
    }

    /** A robot whose belief is the truth. */
    public RobotSnapshot(int number, String label, boolean placed, double x, double y, double theta,
                         List<PartSnapshot> parts) {
        this(number, label, placed, x, y, theta, parts, null);
    }

    /** Where the robot believes it is (x, y, theta), or null when that is where it is. */
    @Override
    public double[] believed() {
        return believed == null ? null : believed.clone();
    }

    /** The believed pose as a body-to-world transform, or null when it is the true one. */
    public RsTransform believedPose() {
        return believed == null ? null : new RsTransform(believed[2], believed[0], believed[1]);
    }

    /** The robot's state now; call on the thread running the simulation's tasks, which changes it. */
    public static RobotSnapshot of(Robot robot) {
        List<PartSnapshot> parts = new ArrayList<>();
        for (RsBodyPart p : robot.getBody().getBodyPartArray()) {
            parts.add(PartSnapshot.of(p));
            if (p instanceof RsActuator) {
                for (RsBodyPart sub : ((RsActuator) p).getPartsArray()) {
                    parts.add(PartSnapshot.of(sub));
                }
            }
        }
        RsTransform pose = robot.pose();
        RsTransform belief = robot.believedPose();
        return new RobotSnapshot(robot.getNumber(), robot.getLabel(), robot.isPlaced(), pose.m13, pose.m23,
                pose.getTheta(), parts, belief == null ? null : new double[] {belief.m13, belief.m23, belief.getTheta()});
    }

    /** The pose as a body-to-world transform. */
    public RsTransform pose() {
        return new RsTransform(theta, x, y);
    }
}
