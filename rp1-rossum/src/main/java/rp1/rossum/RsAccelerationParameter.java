package rp1.rossum;

/**
 * A velocity paired with the acceleration used to reach it: a value a client can use to describe how
 * its actuators ramp up. The simulator's motion model changes speed instantaneously and does not
 * use it.
 */
public class RsAccelerationParameter extends RsComponent {
    private static final long serialVersionUID = 1L;

    public final double velocity;
    public final double acceleration;

    public RsAccelerationParameter(double velocity, double acceleration) {
        this.velocity = velocity;
        this.acceleration = acceleration;
    }
}
