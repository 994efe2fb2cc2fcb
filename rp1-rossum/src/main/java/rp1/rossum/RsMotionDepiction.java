package rp1.rossum;

/**
 * How one point of a robot body moves at an instant: where it is, its velocity, the body's heading
 * and whether the motion is under way. Wheels read it to count encoder intervals (signed speed of the
 * hub) and to draw casters along their direction of travel. Immutable.
 */
public class RsMotionDepiction {
    private final double time;
    private final RsPoint position;
    private final RsVector velocity;
    private final double heading;
    private final boolean moving;

    /**
     * @param time simulation time, seconds
     * @param position the point in world coordinates
     * @param velocity its velocity in world coordinates, m/s
     * @param heading the body's heading, radians
     * @param moving whether the motion is still under way at that time
     */
    public RsMotionDepiction(double time, RsPoint position, RsVector velocity, double heading, boolean moving) {
        this.time = time;
        this.position = new RsPoint(position);
        this.velocity = new RsVector(velocity);
        this.heading = heading;
        this.moving = moving;
    }

    /** Simulation time of the depiction, seconds. */
    public double getTime() {
        return time;
    }

    /** A copy of the point's world position. */
    public RsPoint getPosition() {
        return new RsPoint(position);
    }

    /** A copy of the point's world velocity (m/s). */
    public RsVector getVelocity() {
        return new RsVector(velocity);
    }

    /** The body's heading, radians. */
    public double getHeading() {
        return heading;
    }

    /** Whether the motion was still under way at that time. */
    public boolean isMoving() {
        return moving;
    }

    /**
     * The point's speed, negative when it moves backwards relative to the heading; 0 once the
     * motion has ended.
     */
    public double getSignedSpeed() {
        if (!moving) {
            return 0.0;
        }
        double speed = velocity.magnitude();
        double along = velocity.x * Math.cos(heading) + velocity.y * Math.sin(heading);
        return along < 0.0 ? -speed : speed;
    }

    /** The direction of travel relative to the body's x axis, radians; NaN when the point is still. */
    public double getDirectionInBody() {
        if (velocity.magnitude() < RsVector.NEARLY_ZERO) {
            return Double.NaN;
        }
        return Math.atan2(velocity.y, velocity.x) - heading;
    }
}
