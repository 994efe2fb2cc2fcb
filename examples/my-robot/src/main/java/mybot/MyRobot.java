package mybot;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsProperties;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * A robot to start from: placed at "home", it drives straight ahead for one metre and stops; if it
 * runs into something first it backs off 10 cm. Runs in the simulator (dlcName=mybot.MyRobot) or on
 * its own against a running one: {@code java -cp ... mybot.MyRobot [-port N] [-hostName H]} (the host
 * and port of {@code rossum.ini} otherwise).
 */
public class MyRobot extends RsClient implements RsRunnable {
    /** Metres the robot drives from home. */
    static final double DISTANCE = 1.0;
    /** Metres per second. */
    static final double SPEED = 0.25;

    /** Connects to the simulator named by rossum.ini and the options, and runs until it goes away. */
    public static void main(String[] args) {
        MyRobot robot = new MyRobot();
        try {
            robot.initialize(new RsProperties(args));
        } catch (IOException e) {
            System.err.println(e.getMessage());
            System.exit(1);
        }
        robot.run();
    }

    /** The simulator loads the robot through this constructor. */
    public MyRobot() {
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        sendBodySpecification(body());
        addPlacementEventHandler(e -> {
            if (e.valid) {
                log("placed at " + e.x + ", " + e.y + "; driving " + DISTANCE + " m");
                sendMotionRequest(new RsMotionRequest(SPEED, 0.0, DISTANCE / SPEED));
            } else {
                log("placement at home refused: another robot stands there, or the plan has no home");
            }
        });
        addMotionHaltedEventHandler(e -> {
            if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
                log("bumped at " + e.x + ", " + e.y + "; backing off");
                sendMotionRequest(new RsMotionRequest(-SPEED, 0.0, 0.1 / SPEED));
            } else {
                log("stopped at " + e.x + ", " + e.y);
            }
        });
        sendPlacementRequest("home");
    }

    /** A round chassis on two wheels. */
    static RsBody body() {
        RsBody body = new RsBody("MyRobot");
        RsDifferentialSteering wheels = new RsDifferentialSteering(0.18, 0.05);
        wheels.addDefaultWheels(0.05, 0.02);
        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, 0.12);
        chassis.setFillColor(Color.orange);
        body.addPart(chassis);
        body.addPart(wheels);
        return body;
    }
}
