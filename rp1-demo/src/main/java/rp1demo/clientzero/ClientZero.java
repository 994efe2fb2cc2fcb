package rp1demo.clientzero;

import java.awt.Color;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsDifferentialSteering;

/**
 * The body plan of ClientZero, as the original's user's guide draws it: a round chassis 0.3 m
 * across on two wheels, with a target sensor named "head" on its front looking straight ahead over
 * 45 degrees and 1 m. Not meant to be instantiated: {@link #build()} is all there is.
 */
public final class ClientZero {
    /** Radius of the chassis, metres. */
    public static final double RADIUS = 0.15;
    /** Where the head's detector sits ahead of the axle centre, metres. */
    public static final double HEAD_X = 0.16;
    /** How far the head sees, metres. */
    public static final double HEAD_RANGE = 1.0;
    /** Name of the painter part of {@link #buildWithPainter}. */
    public static final String PEN = "pen";

    private ClientZero() {
    }

    /**
     * A new ClientZero body. The wheels are added last so that they are drawn over the chassis
     * (parts are drawn in the order they were added).
     */
    public static RsBody build() {
        RsBody body = new RsBody("ClientZero");
        double trackWidth = 0.18;
        double driveWheelRadius = 0.075;
        RsDifferentialSteering wheelSystem = new RsDifferentialSteering(trackWidth, driveWheelRadius);
        wheelSystem.addDefaultWheels(driveWheelRadius, 0.03);
        wheelSystem.setFillColor(Color.darkGray);
        wheelSystem.setLineColor(Color.darkGray);

        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, RADIUS);
        chassis.setName("main chassis");
        chassis.setFillColor(Color.lightGray);
        chassis.setLineColor(Color.darkGray);
        body.addPart(chassis);

        double[] headOutline = {
            0.09, -0.025,
            HEAD_X, -0.025,
            HEAD_X, 0.025,
            0.09, 0.025};
        RsBodySensor head = new RsBodyTargetSensor(headOutline, 4,
                HEAD_X, 0.0, 0.0, Math.toRadians(45.0), HEAD_RANGE, 3, 3);
        head.setName("head");
        head.setFillColor(Color.blue);
        head.setLineColor(Color.blue);
        body.addPart(head);

        body.addPart(wheelSystem);
        return body;
    }

    /**
     * ClientZero with a painter named {@value #PEN} under its axle centre that, once activated,
     * leaves a 1 cm trail of {@code trailColor} behind the robot: the demos that drive on their own
     * use it to show where they went.
     */
    public static RsBody buildWithPainter(Color trailColor) {
        RsBody body = build();
        RsBodyPainter pen = new RsBodyPainter(new double[] {-0.01, -0.01, 0.01, -0.01, 0.01, 0.01, -0.01, 0.01}, 4);
        pen.setName(PEN);
        pen.setTrailerPosition(0.0, 0.0);
        pen.setTrailerWidth(0.01);
        pen.setPaintColor(trailColor);
        body.addPart(pen);
        return body;
    }
}
