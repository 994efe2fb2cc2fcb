package rp1.view;

import java.awt.Color;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsDifferentialSteering;

/** The original user's guide's ClientZero body, optionally with a painter at its centre. */
final class ClientZero {
    static final double RADIUS = 0.15;
    static final double TRACK_WIDTH = 0.18;
    /** Where a point of the head (the blue target sensor) lies, body coordinates. */
    static final double HEAD_X = 0.125;
    /** The trail colour of {@link #withPainter()}. */
    static final Color TRAIL = Color.magenta;
    /** The trail width of {@link #withPainter()}, metres. */
    static final double TRAIL_WIDTH = 0.02;

    private ClientZero() {
    }

    /** Chassis, head, then the wheel system with its two default wheels, coloured as in the guide. */
    static RsBody build() {
        RsBody body = new RsBody("ClientZero");
        RsDifferentialSteering wheelSystem = new RsDifferentialSteering(TRACK_WIDTH, 0.075);
        wheelSystem.addDefaultWheels(0.075, 0.03);
        wheelSystem.setFillColor(Color.darkGray);
        wheelSystem.setLineColor(Color.darkGray);
        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, RADIUS);
        chassis.setName("main chassis");
        chassis.setFillColor(Color.lightGray);
        chassis.setLineColor(Color.darkGray);
        body.addPart(chassis);
        double[] d1 = {0.09, -0.025, 0.16, -0.025, 0.16, 0.025, 0.09, 0.025};
        RsBodySensor head = new RsBodyTargetSensor(d1, 4, 0.16, 0.0, 0.0, Math.toRadians(45), 1.0, 3, 3);
        head.setName("head");
        head.setFillColor(Color.blue);
        head.setLineColor(Color.blue);
        body.addPart(head);
        body.addPart(wheelSystem);
        return body;
    }

    /** ClientZero with a small painter whose trailer is at the body origin, set up to paint magenta. */
    static RsBody withPainter() {
        RsBody body = build();
        RsBodyPainter painter = new RsBodyPainter(new double[] {-0.01, -0.01, 0.01, -0.01, 0.01, 0.01, -0.01, 0.01}, 4);
        painter.setName("brush");
        painter.setTrailerPosition(0.0, 0.0);
        painter.setTrailerWidth(TRAIL_WIDTH);
        painter.setPaintColor(TRAIL);
        body.addPart(painter);
        return body;
    }

    static RsBodyPainter painterOf(RsBody body) {
        return body.getBodyPainterArray()[0];
    }
}
