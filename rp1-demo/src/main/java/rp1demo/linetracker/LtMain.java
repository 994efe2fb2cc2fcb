package rp1demo.linetracker;

import java.io.IOException;
import java.util.Locale;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1demo.Standalone;

/**
 * The line tracker's connection to the simulator: it places the robot at "start" on the line and
 * from then on passes every change its paint sensors report to the {@link LineFollower}, driving
 * the wheels at the speeds it answers.
 */
public class LtMain extends RsClient implements RsRunnable {
    /** Wheel speed on the straight, metres per second. */
    public static final double CRUISE = 0.15;
    /**
     * How long each wheel command lasts, seconds. A new command replaces it on the next change the
     * eyes see; should none come, the command is simply repeated.
     */
    public static final double COMMAND_DURATION = 60.0;

    private final LineFollower follower = new LineFollower(CRUISE);
    private RsBody body;
    private RsDifferentialSteering wheels;
    private RsBodyPaintSensor leftEye;
    private LineFollower.WheelSpeeds driving;
    private volatile boolean placed;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new LtMain());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public LtMain() {
        super();
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = LineTracker.build();
        wheels = (RsDifferentialSteering) body.wheelSystem;
        leftEye = (RsBodyPaintSensor) body.getPartByName(LineTracker.LEFT_EYE);
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addPaintSensorEventHandler(leftEye, this::sensed);
        addPaintSensorEventHandler((RsBodyPaintSensor) body.getPartByName(LineTracker.RIGHT_EYE), this::sensed);
        addMotionHaltedEventHandler(this::halted);
        sendPlacementRequest("start");
    }

    public RsBody getBody() {
        return body;
    }

    /** The line-following logic. */
    public LineFollower getFollower() {
        return follower;
    }

    private void placed(RsPlacementEvent e) {
        if (!e.valid) {
            log("Placement \"" + e.name + "\" failed: this demo needs FloorPlans/linetrack.txt");
            return;
        }
        placed = true;
        log("On the line at \"" + e.name + "\"; following it");
        drive(follower.command());
    }

    private void sensed(RsPaintSensorEvent e) {
        if (!placed) {
            return;
        }
        LineFollower.Eye eye = e.sensorID == leftEye.getID() ? LineFollower.Eye.LEFT : LineFollower.Eye.RIGHT;
        boolean wasLost = follower.isLost();
        LineFollower.WheelSpeeds speeds = follower.sensed(eye, e.status);
        verbose(String.format(Locale.ROOT, "%s eye %s (region %d)", eye, e.status ? "on the line" : "off it", e.region));
        if (follower.isLost() && !wasLost) {
            log(String.format(Locale.ROOT, "Lost the line at (%.3f, %.3f); searching", e.x, e.y));
        } else if (wasLost && !follower.isLost()) {
            log("Found the line again");
        }
        if (!speeds.equals(driving)) {
            drive(speeds);
        }
    }

    private void halted(RsMotionHaltedEvent e) {
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            log("Ran into a wall; stopped");
            placed = false;
        } else if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COMPLETION && placed) {
            drive(driving);
        }
    }

    private void drive(LineFollower.WheelSpeeds speeds) {
        driving = speeds;
        sendMotionRequest(wheels.getMotionRequestUsingWheelVelocities(speeds.left(), speeds.right(), COMMAND_DURATION));
    }
}
