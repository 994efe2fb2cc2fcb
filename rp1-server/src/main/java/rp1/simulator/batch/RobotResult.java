package rp1.simulator.batch;

/**
 * One robot at the end of a run.
 *
 * @param name       the robot's name (its body's), with {@code #N} added when robots share a name
 * @param x          where it ended, metres
 * @param y          where it ended, metres
 * @param heading    its heading at the end, radians
 * @param distance   how far its body origin travelled, metres
 * @param collisions how many of its motions ended in a collision
 * @param events     how many events its client was sent
 */
public record RobotResult(String name, double x, double y, double heading, double distance, int collisions,
                          long events) {
}
