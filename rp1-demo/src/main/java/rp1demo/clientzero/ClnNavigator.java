package rp1demo.clientzero;

import rp1demo.navigation.Pose;

/**
 * ClientZero's robot logic, such as it is: it remembers where the user last clicked and, once told
 * where the robot is, says where that point lies from the robot's point of view and whether to go
 * there or only turn to face it. It also decides to back away from a wall it ran into, so that it
 * is free to turn again.
 */
public final class ClnNavigator {
    /** How far to back away from a wall after bumping into it, metres. */
    public static final double BACK_OFF_DISTANCE = 0.05;

    /**
     * A goal seen from the robot.
     *
     * @param go whether to drive there (else only turn to face it)
     * @param x  metres ahead of the robot
     * @param y  metres to its left
     */
    public record Aim(boolean go, double x, double y) {
    }

    private boolean pending;
    private boolean go;
    private double goalX;
    private double goalY;

    /**
     * The user clicked at (x, y): the primary button means "go there", any other "face it".
     * Replaces a goal not yet acted on.
     */
    public void clicked(boolean primaryButton, double x, double y) {
        pending = true;
        go = primaryButton;
        goalX = x;
        goalY = y;
    }

    /** Whether a click waits for the robot's position. */
    public boolean hasGoal() {
        return pending;
    }

    /** The waiting goal as seen from {@code pose} (and no longer waiting), or null if there is none. */
    public Aim aimFrom(Pose pose) {
        if (!pending) {
            return null;
        }
        pending = false;
        double[] r = pose.toRobotFrame(goalX, goalY);
        return new Aim(go, r[0], r[1]);
    }
}
