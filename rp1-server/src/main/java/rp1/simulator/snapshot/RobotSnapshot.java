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
 */
public record RobotSnapshot(int number, String label, boolean placed, double x, double y, double theta,
                            List<PartSnapshot> parts) {

    /** Copies the parts list. */
    public RobotSnapshot {
        parts = List.copyOf(parts);
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
        return new RobotSnapshot(robot.getNumber(), robot.getLabel(), robot.isPlaced(), pose.m13, pose.m23,
                pose.getTheta(), parts);
    }

    /** The pose as a body-to-world transform. */
    public RsTransform pose() {
        return new RsTransform(theta, x, y);
    }
}
