package rp1.bench;

import java.io.IOException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * A wall-avoiding wanderer for the throughput benchmark: a 5 cm round robot with a differential
 * drive, a forward range sensor (30 cm) and a forward target sensor (1 m, 90 degrees). It drives
 * ahead; when the range sensor sees something closer than 10 cm, or it bumps into something, it turns
 * on the spot for a moment and drives on. A heartbeat every 0.1 s keeps it company.
 */
public class Wanderer extends RsClient {
    /** Events received by all wanderers. */
    static final AtomicLong EVENTS = new AtomicLong();
    /** Wanderers placed on the floor. */
    static final AtomicInteger PLACED = new AtomicInteger();

    private static final double RADIUS = 0.025;
    private static final double SPEED = 0.2;
    private static final double TURN_RATE = Math.PI;
    private static final double CLOSE = 0.1;

    private volatile boolean turning;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = body();
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addHeartbeatEventHandler(this::count);
        addTimeoutEventHandler(this::count);
        addMotionStartedEventHandler(this::count);
        addRangeSensorEventHandler((RsBodyRangeSensor) body.getPartByName("sonar"), this::range);
        addTargetSensorEventHandler((RsBodyTargetSensor) body.getPartByName("eye"), this::count);
        sendHeartbeatRequest(0.1);
        sendPlacementRequest("$random");
    }

    private static RsBody body() {
        RsBody body = new RsBody("wanderer");
        body.addPart(new RsBodyCircle(0.0, 0.0, RADIUS));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.04, 0.01);
        drive.addDefaultWheels(0.01, 0.005);
        body.addPart(drive);
        double[] box = {0.015, -0.005, 0.025, -0.005, 0.025, 0.005, 0.015, 0.005};
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(box, 4, 0.025, 0.0, 0.0, 0.3, 10);
        sonar.setName("sonar");
        body.addPart(sonar);
        RsBodyTargetSensor eye = new RsBodyTargetSensor(box, 4, 0.025, 0.0, 0.0, Math.PI / 2, 1.0, 3, 4);
        eye.setName("eye");
        body.addPart(eye);
        return body;
    }

    private void count(RsEvent e) {
        EVENTS.incrementAndGet();
    }

    private void placed(RsPlacementEvent e) {
        count(e);
        if (!e.valid) {
            sendPlacementRequest("$random");
            return;
        }
        PLACED.incrementAndGet();
        ahead();
    }

    private void ahead() {
        turning = false;
        sendMotionRequest(new RsMotionRequest(SPEED, 0.0, 1000.0));
    }

    private void turn() {
        turning = true;
        sendMotionRequest(new RsMotionRequest(0.0, TURN_RATE, 0.5));
    }

    private void range(RsRangeSensorEvent e) {
        count(e);
        if (e.status && e.range < CLOSE && !turning) {
            turn();
        }
    }

    private void halted(RsMotionHaltedEvent e) {
        count(e);
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            turn();
        } else {
            ahead();
        }
    }
}
