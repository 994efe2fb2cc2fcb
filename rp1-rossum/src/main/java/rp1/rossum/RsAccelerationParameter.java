package rp1.rossum;

/**
 * A velocity paired with the acceleration used to reach it: a value a client can use to describe how
 * its actuators ramp up. The simulator's motion model changes speed instantaneously and does not
 * use it.
 */
public class RsAccelerationParameter extends RsComponent {
    private static final long serialVersionUID = 1L;

    /** The velocity, in the client's units (m/s or rad/s). */
    public final double velocity;
    /** The acceleration used to reach {@link #velocity}, per second. */
    public final double acceleration;

    /**
     * A velocity and the acceleration that reaches it.
     *
     * @param velocity the velocity
     * @param acceleration the acceleration used to reach it
     */
    public RsAccelerationParameter(double velocity, double acceleration) {
        this.velocity = velocity;
        this.acceleration = acceleration;
    }
}
