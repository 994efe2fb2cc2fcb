package rp1.bench;

import java.io.IOException;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * The throughput benchmark's robot, a wanderer: a 16 cm round robot with a differential drive, a
 * forward range sensor (1 m, 10 bins) and a front bumper. It drives ahead; when the range sensor sees
 * something closer than 30 cm, or the bumper or a collision stops it, it turns left on the spot by
 * 40 to 160 degrees (drawn from a random source of its own, seeded by the order wanderers were
 * created in) and drives on. A motion blocked at its start halts at once with
 * duration 0; then it waits a fifth of a second before trying again, rather than asking again at the
 * same instant for ever. A heartbeat every 0.1 s keeps it company. It keeps the library's event loop,
 * so a server loads it with direct delivery.
 */
public class Wanderer extends RsClient {
    /** Events received by all wanderers in this process. */
    static final AtomicLong EVENTS = new AtomicLong();
    /** Wanderers placed on the floor. */
    static final AtomicInteger PLACED = new AtomicInteger();

    private static final double RADIUS = 0.08;
    private static final double SPEED = 0.3;
    private static final double TURN_RATE = Math.PI / 2;
    private static final double CLOSE = 0.3;

    private static final AtomicInteger CREATED = new AtomicInteger();

    private final Random random = new Random(CREATED.incrementAndGet());
    private boolean turning;

    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = body();
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addMotionStartedEventHandler(Wanderer::count);
        addHeartbeatEventHandler(Wanderer::count);
        addTimeoutEventHandler(e -> {
            count(e);
            turn();
        });
        addRangeSensorEventHandler((RsBodyRangeSensor) body.getPartByName("sonar"), this::range);
        addContactSensorEventHandler((RsBodyContactSensor) body.getPartByName("bumper"), this::bumped);
        sendHeartbeatRequest(0.1);
        sendPlacementRequest("$random");
    }

    static RsBody body() {
        RsBody body = new RsBody("wanderer");
        body.addPart(new RsBodyCircle(0.0, 0.0, RADIUS));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.12, 0.03);
        drive.addDefaultWheels(0.02, 0.01);
        body.addPart(drive);
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(new double[] {0.06, -0.01, 0.08, -0.01, 0.08, 0.01, 0.06, 0.01},
                4, RADIUS, 0.0, 0.0, 1.0, 10);
        sonar.setName("sonar");
        body.addPart(sonar);
        RsBodyContactSensor bumper = new RsBodyContactSensor(new double[] {0.07, -0.05, 0.09, -0.05, 0.09, 0.05,
            0.07, 0.05}, 4);
        bumper.setName("bumper");
        body.addPart(bumper);
        return body;
    }

    private static void count(RsEvent e) {
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
        sendMotionRequest(new RsMotionRequest(0.0, TURN_RATE, 0.45 + 1.3 * random.nextDouble()));
    }

    private void range(RsRangeSensorEvent e) {
        count(e);
        if (e.status && e.range < CLOSE && !turning) {
            turn();
        }
    }

    private void bumped(RsContactSensorEvent e) {
        count(e);
    }

    private void halted(RsMotionHaltedEvent e) {
        count(e);
        if (e.duration == 0.0) {
            sendTimeoutRequest(0.2);
        } else if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION || !turning) {
            turn();
        } else {
            ahead();
        }
    }
}
