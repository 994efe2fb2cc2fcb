package rp1.web;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.request.RsMotionRequest;

/**
 * A loaded client for the page's tests: ClientZero's body with a painter, a range sensor and a
 * target sensor, placed at "home" in the White Room, painting as it goes. It drives forward and
 * turns in turn until it has halted {@link #LEGS} times; a mouse click on the floor sends it forward
 * again, so a click is seen as the robot moving.
 */
public class Wanderer extends RsClient {
    /** How many motions it makes by itself. */
    static final int LEGS = 12;
    private int legs;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = new RsBody("Wanderer");
        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, 0.15);
        chassis.setFillColor(Color.lightGray);
        chassis.setLineColor(Color.darkGray);
        body.addPart(chassis);
        RsBodyTargetSensor eye = new RsBodyTargetSensor(new double[] {0.09, -0.025, 0.16, -0.025, 0.16, 0.025,
            0.09, 0.025}, 4, 0.16, 0.0, 0.0, Math.toRadians(45), 3.0, 3, 3);
        body.addPart(eye);
        RsBodyRangeSensor ranger = new RsBodyRangeSensor(new double[] {0.1, 0.06, 0.13, 0.06, 0.13, 0.09, 0.1, 0.09},
                4, 0.13, 0.075, 0.5, 2.0, 20);
        body.addPart(ranger);
        RsDifferentialSteering wheels = new RsDifferentialSteering(0.18, 0.075);
        wheels.addDefaultWheels(0.075, 0.03);
        body.addPart(wheels);
        RsBodyPainter painter = new RsBodyPainter(new double[] {-0.01, -0.01, 0.01, -0.01, 0.01, 0.01, -0.01, 0.01}, 4);
        painter.setTrailerPosition(0.0, 0.0);
        painter.setTrailerWidth(0.02);
        painter.setPaintColor(Color.magenta);
        body.addPart(painter);
        sendBodySpecification(body);
        addPlacementEventHandler(e -> {
            sendPainterActivationRequest(painter);
            next();
        });
        addMotionHaltedEventHandler(e -> next());
        addMouseClickEventHandler(e -> sendMotionRequest(new RsMotionRequest(0.3, 0.0, 1.0)));
        addRangeSensorEventHandler(ranger, e -> { });
        addTargetSensorEventHandler(eye, e -> { });
        sendPlacementRequest("home");
    }

    /** How many motions it makes by itself: {@link #LEGS}. */
    protected int legs() {
        return LEGS;
    }

    private void next() {
        if (legs >= legs()) {
            return;
        }
        legs++;
        sendMotionRequest(legs % 2 == 1 ? new RsMotionRequest(0.3, 0.0, 1.5) : new RsMotionRequest(0.0, 1.0, 1.2));
    }
}
