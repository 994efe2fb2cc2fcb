package rp1demo.ackerman;

import java.io.IOException;
import java.util.Locale;

import rp1.rossum.RsAckermanSteering;
import rp1.rossum.RsBody;
import rp1.rossum.RsClient;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1demo.Standalone;
import rp1demo.adapter.Poses;

/**
 * The Ackerman demo's connection to the simulator (docs/guide.md section 2; the original's user's
 * guide calls its own Ackerman demo "the simplest demo application"): the car is placed at "home"
 * and, ten times a second, asks where it is and sets its drive wheels' speed and its steering angle
 * as the {@link CourseDriver} says, through the steering system's actuator controls, until it is
 * back near home.
 */
public class Main extends RsClient implements RsRunnable {
    /**
     * The course on FloorPlans/ackerman.txt (a 10 m by 8 m hall, cones at (5, 2.5), (5, 5.5) and
     * (8, 4), home at (2, 4) facing east): between the first two cones, anticlockwise round the third,
     * back west north of the second and round to home. Corners x, y in metres. A fresh array each
     * time: an array in a static field is state a sweep's runs would share.
     */
    static double[] course() {
        return new double[] {
            2.0, 4.0,
            4.0, 4.0,
            6.2, 4.0,
            7.4, 2.96,
            8.6, 2.96,
            9.2, 4.0,
            8.6, 5.04,
            7.4, 5.04,
            6.0, 6.6,
            4.0, 6.8,
            2.4, 6.8,
            1.2, 6.0,
            0.9, 5.0,
            1.4, 4.1,
            2.5, 4.0
        };
    }

    /** Driving speed, metres per second. */
    public static final double SPEED = 1.0;
    /** How often the driver looks where the car is, seconds. */
    public static final double CONTROL_PERIOD = 0.1;
    /** How far ahead on the course the driver aims, metres. */
    public static final double LOOKAHEAD = 1.0;

    private RsBody body;
    private RsAckermanSteering steering;
    private CourseDriver driver;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new Main());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public Main() {
        super();
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = Car.build();
        steering = (RsAckermanSteering) body.wheelSystem;
        driver = new CourseDriver(course(), Car.WHEEL_BASE, LOOKAHEAD, SPEED, steering.getMaxAbsSteeringAngle(), this::log);
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addHeartbeatEventHandler(this::tick);
        addPositionEventHandler(this::positioned);
        addMotionHaltedEventHandler(this::halted);
        sendPlacementRequest("home");
    }

    public RsBody getBody() {
        return body;
    }

    /** The driver following the course. */
    public CourseDriver getDriver() {
        return driver;
    }

    private void placed(RsPlacementEvent e) {
        if (!e.valid) {
            log("Placement \"" + e.name + "\" failed: this demo needs FloorPlans/ackerman.txt");
            return;
        }
        log(String.format(Locale.ROOT, "At \"%s\"; driving the %.1f m course", e.name, driver.length()));
        sendHeartbeatRequest(CONTROL_PERIOD);
    }

    private void tick(RsHeartbeatEvent e) {
        sendPositionRequest();
    }

    private void positioned(RsPositionEvent e) {
        CourseDriver.Steering s = driver.steer(Poses.of(e));
        if (s == null) {
            sendHeartbeatCancellationRequest();
            sendHaltRequest();
            return;
        }
        sendActuatorControlRequest(steering.getControlRequestForWheelRotationAndSteeringAngle(
                steering.mapVelocityToWheelRotationalVelocity(s.speed()), s.angle()));
    }

    private void halted(RsMotionHaltedEvent e) {
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            log("Ran into something at " + Poses.of(e) + "; stopping");
            sendHeartbeatCancellationRequest();
        } else if (driver.isFinished()) {
            log("Parked at " + Poses.of(e));
        }
    }
}
