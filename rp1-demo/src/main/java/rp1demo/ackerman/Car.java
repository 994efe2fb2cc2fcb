package rp1demo.ackerman;

import java.awt.Color;

import rp1.rossum.RsAckermanSteering;
import rp1.rossum.RsBody;
import rp1.rossum.RsBodyShape;

/**
 * The car's body: a 0.9 m by 0.5 m chassis on four wheels, the front pair steered (Ackerman
 * geometry). The body's origin is the middle of the rear axle, the point the motion model moves.
 */
public final class Car {
    /** Distance between the axles, metres. */
    public static final double WHEEL_BASE = 0.6;
    /** Distance between the left and right wheels, metres. */
    public static final double TRACK_WIDTH = 0.4;
    /** Radius of the driven wheels, metres. */
    public static final double WHEEL_RADIUS = 0.1;
    /** Steering limit of the inner front wheel, radians. */
    public static final double MAX_INNER_ANGLE = Math.toRadians(40.0);

    private Car() {
    }

    /** A new car body; the wheels are added after the chassis so that they are drawn on top. */
    public static RsBody build() {
        RsBody body = new RsBody("Ackerman car");
        RsBodyShape chassis = new RsBodyShape(new double[] {
            -0.15, -0.25,
            0.75, -0.25,
            0.75, 0.25,
            -0.15, 0.25}, 4);
        chassis.setName("chassis");
        chassis.setFillColor(Color.cyan);
        chassis.setLineColor(Color.blue);
        body.addPart(chassis);

        RsAckermanSteering steering = new RsAckermanSteering(TRACK_WIDTH, WHEEL_BASE, WHEEL_RADIUS, MAX_INNER_ANGLE, false);
        steering.addDefaultWheels(WHEEL_RADIUS, 0.06, 0.08, 0.02);
        steering.setFillColor(Color.darkGray);
        steering.setLineColor(Color.black);
        body.addPart(steering);
        return body;
    }
}
