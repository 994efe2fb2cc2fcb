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
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * The "scale arena" wanderer of the peers' workload (docs/performance.md): a disc of radius 0.1 m with a
 * differential drive, one forward range sensor at its front edge (0.5 m) and a front bumper. Every
 * 0.1 s (its heartbeat, the control period) it decides: driving straight at 0.5 m/s, it pivots at
 * 2 rad/s in a random direction for a random 0.3 to 1.3 s once the range sensor reports something, the
 * bumper is hot or a motion was halted by a collision; pivoting, it drives on once the pivot's time is
 * up. Each wanderer is placed at the plan's placement {@code sK}, K the order it was created in, and
 * draws from a random source seeded by K. It keeps the library's event loop, so it is called directly.
 */
public class ScaleWanderer extends RsClient {
    /** Events received by all scale wanderers in this process. */
    static final AtomicLong EVENTS = new AtomicLong();
    /** Scale wanderers placed on the floor. */
    static final AtomicInteger PLACED = new AtomicInteger();

    static final double RADIUS = 0.1;
    private static final double CRUISE = 0.5;
    private static final double PIVOT = 2.0;
    private static final double RANGE = 0.5;
    private static final double PERIOD = 0.1;
    private static final double DRIVE_FOR = 1e6;

    private static final AtomicInteger CREATED = new AtomicInteger();

    private final int index = CREATED.getAndIncrement();
    private final Random random = new Random(index + 1);
    private boolean turning;
    private double turnUntil;
    private boolean seen;
    private boolean bumped;
    private boolean stalled;

    /**
     * The next wanderers made belong to a new world: they count from 0 again (placements {@code s0},
     * {@code s1}, ..., and their random sources), and none is placed yet.
     */
    static void startAnew() {
        CREATED.set(0);
        PLACED.set(0);
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        RsBody body = body();
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addMotionStartedEventHandler(ScaleWanderer::count);
        addHeartbeatEventHandler(this::control);
        addRangeSensorEventHandler((RsBodyRangeSensor) body.getPartByName("range"), this::range);
        addContactSensorEventHandler((RsBodyContactSensor) body.getPartByName("bumper"), this::bumper);
        sendPlacementRequest("s" + index);
    }

    static RsBody body() {
        RsBody body = new RsBody("scale wanderer");
        body.addPart(new RsBodyCircle(0.0, 0.0, RADIUS));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.16, 0.03);
        drive.addDefaultWheels(0.03, 0.01);
        body.addPart(drive);
        RsBodyRangeSensor range = new RsBodyRangeSensor(new double[] {0.08, -0.01, 0.1, -0.01, 0.1, 0.01, 0.08, 0.01},
                4, RADIUS, 0.0, 0.0, RANGE, 1);
        range.setName("range");
        body.addPart(range);
        RsBodyContactSensor bumper = new RsBodyContactSensor(new double[] {0.09, -0.05, 0.105, -0.05, 0.105, 0.05,
            0.09, 0.05}, 4);
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
            throw new IllegalStateException("scale wanderer " + index + " could not be placed at s" + index);
        }
        PLACED.incrementAndGet();
        sendHeartbeatRequest(PERIOD);
        drive();
    }

    private void drive() {
        turning = false;
        stalled = false;
        sendMotionRequest(new RsMotionRequest(CRUISE, 0.0, DRIVE_FOR));
    }

    private void control(RsHeartbeatEvent e) {
        count(e);
        if (turning) {
            if (e.simTime >= turnUntil) {
                drive();
            }
        } else if (seen || bumped || stalled) {
            stalled = false;
            turning = true;
            double direction = random.nextDouble() < 0.5 ? PIVOT : -PIVOT;
            double duration = 0.3 + random.nextDouble();
            turnUntil = e.simTime + duration;
            sendMotionRequest(new RsMotionRequest(0.0, direction, duration));
        }
    }

    private void range(RsRangeSensorEvent e) {
        count(e);
        seen = e.status;
    }

    private void bumper(RsContactSensorEvent e) {
        count(e);
        bumped = e.status;
    }

    private void halted(RsMotionHaltedEvent e) {
        count(e);
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            stalled = true;
        }
    }
}
