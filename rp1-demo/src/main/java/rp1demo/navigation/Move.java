package rp1demo.navigation;

/**
 * One move of a robot that can turn on the spot: a {@link Turn} in place or a straight
 * {@link Forward} run. How fast it is done is up to the robot's interface.
 */
public sealed interface Move {

    /**
     * Turning on the spot.
     *
     * @param angle radians, positive anticlockwise (to the left)
     */
    record Turn(double angle) implements Move {
    }

    /**
     * Driving straight ahead (backwards if negative).
     *
     * @param distance metres
     */
    record Forward(double distance) implements Move {
    }
}
