package rp1demo.firefighter;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsClient;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1demo.adapter.MoveRequests;
import rp1demo.adapter.NavPlans;
import rp1demo.adapter.Poses;
import rp1demo.clientzero.ClientZero;
import rp1demo.navigation.Move;

/**
 * The fire fighter's connection to the simulator: a ClientZero body whose "head" is the candle
 * sensor and which leaves a red trail, the floor plan's navigation network for the search, and the
 * "home" placement to start from. Events go to the {@link FireFighter}; its commands become
 * requests.
 */
public class FfMain extends RsClient implements RsRunnable, FireFighter.Robot {
    /** Straight-line speed, metres per second. */
    public static final double SPEED = 0.3;
    /** Turning rate, radians per second (a quarter turn a second). */
    public static final double TURN_RATE = Math.PI / 2.0;
    /** Distance from the robot's centre to the candle at which it stops, metres. */
    public static final double STANDOFF = 0.4;
    /** Candles farther than this from where the robot looks around are in another room, metres. */
    public static final double REACH = 1.2;

    private final MoveRequests moves = new MoveRequests(SPEED, TURN_RATE);
    private RsBody body;
    private volatile FireFighter fireFighter;
    private RsPlacementEvent placement;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     *
     * @throws IOException if the simulator cannot be reached
     */
    public static void main(String[] args) throws IOException {
        FfMain c = new FfMain();
        c.initialize();
        c.run();
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public FfMain() {
        super();
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = ClientZero.buildWithPainter(Color.red);
        sendBodySpecification(body);
        addPlanEventHandler(this::planReceived);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addTargetSensorEventHandler((RsBodyTargetSensor) body.getPartByName("head"), this::sighting);
        sendPlanRequest();
        sendPlacementRequest("home");
    }

    public RsBody getBody() {
        return body;
    }

    /** The search strategy, once the floor plan has arrived (else null). */
    public FireFighter getFireFighter() {
        return fireFighter;
    }

    private void planReceived(RsPlanEvent e) {
        if (e.plan instanceof RsPlan plan) {
            fireFighter = new FireFighter(NavPlans.network(plan), STANDOFF, REACH, this, this::log);
            begin();
        }
    }

    private void placed(RsPlacementEvent e) {
        if (!e.valid) {
            log("Placement \"" + e.name + "\" failed; the fire fighter cannot start");
            return;
        }
        placement = e;
        sendPainterActivationRequest(pen());
        begin();
    }

    /** Starts the search once both the plan and the placement have come, whichever came first. */
    private void begin() {
        if (fireFighter != null && placement != null) {
            fireFighter.start(Poses.of(placement));
        }
    }

    private void halted(RsMotionHaltedEvent e) {
        if (fireFighter == null) {
            return;
        }
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            fireFighter.blocked(Poses.of(e));
        } else {
            fireFighter.moveEnded(Poses.of(e));
        }
    }

    private void sighting(RsTargetSensorEvent e) {
        if (fireFighter == null) {
            return;
        }
        if (e.status) {
            double[] at = Poses.targetPosition(e);
            fireFighter.candleInSight(e.getNameOfObjectDetected(), at[0], at[1]);
        } else {
            fireFighter.candleOutOfSight();
        }
    }

    private RsBodyPainter pen() {
        return (RsBodyPainter) body.getPartByName(ClientZero.PEN);
    }

    @Override
    public void drive(Move move) {
        sendMotionRequest(moves.toRequest(move));
    }

    @Override
    public void stop() {
        sendHaltRequest();
    }

    @Override
    public void finished(boolean success) {
        sendPainterDeactivationRequest(pen());
        log(success ? "Fire fighter: candle found" : "Fire fighter: search over, no candle found");
    }
}
