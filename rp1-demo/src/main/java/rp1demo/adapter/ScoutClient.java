package rp1demo.adapter;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsClient;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1demo.clientzero.ClientZero;
import rp1demo.navigation.Move;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.Pose;

/**
 * The simulator side of the demos that find their own way on the floor plan's navigation network
 * (the autopilot and the fire fighter): a ClientZero body that leaves a trail, the plan and the
 * "home" placement asked for, the robot logic started once both have come (in whichever order), and
 * its {@link Move}s sent as motion requests. Subclasses supply the logic.
 */
public abstract class ScoutClient extends RsClient implements RsRunnable {
    /** Straight-line speed, metres per second. */
    public static final double SPEED = 0.3;
    /** Turning rate, radians per second (a quarter turn a second). */
    public static final double TURN_RATE = Math.PI / 2.0;
    /** The placement the robot starts from. */
    public static final String HOME = "home";

    private final MoveRequests moves = new MoveRequests(SPEED, TURN_RATE);
    private final Color trailColor;
    private RsBody body;
    private NavNetwork network;
    private Pose start;

    /** @param trailColor colour of the trail the robot leaves */
    protected ScoutClient(Color trailColor) {
        this.trailColor = trailColor;
    }

    /** Sends the body, registers the handlers and asks for the plan and the "home" placement. */
    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = ClientZero.buildWithPainter(trailColor);
        sendBodySpecification(body);
        addPlanEventHandler(this::planReceived);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addHandlers();
        sendPlanRequest();
        sendPlacementRequest(HOME);
    }

    /** The body sent to the simulator (null before {@link #initialize()}). */
    public RsBody getBody() {
        return body;
    }

    /** Registers the subclass's own handlers, before the plan and the placement are asked for. */
    protected void addHandlers() {
    }

    /** The plan and the placement are in: start the robot logic from {@code pose}. */
    protected abstract void begin(NavNetwork network, Pose pose);

    /** A move completed, or was stopped on request, with the robot at {@code pose}. */
    protected abstract void moveEnded(Pose pose);

    /** A move was cut short by a collision, the robot at {@code pose}. */
    protected abstract void collided(Pose pose);

    /** Starts {@code move}, replacing any under way. */
    public void drive(Move move) {
        sendMotionRequest(moves.toRequest(move));
    }

    /** Stops painting the trail. */
    protected void liftPen() {
        sendPainterDeactivationRequest(pen());
    }

    private RsBodyPainter pen() {
        return (RsBodyPainter) body.getPartByName(ClientZero.PEN);
    }

    private void planReceived(RsPlanEvent e) {
        if (e.plan instanceof RsPlan plan) {
            network = NavPlans.network(plan);
            beginWhenReady();
        }
    }

    private void placed(RsPlacementEvent e) {
        if (!e.valid) {
            log("Placement \"" + e.name + "\" failed: this robot needs a floor plan with a placement \"" + HOME + "\"");
            return;
        }
        start = Poses.of(e);
        sendPainterActivationRequest(pen());
        beginWhenReady();
    }

    private void beginWhenReady() {
        if (network != null && start != null) {
            begin(network, start);
        }
    }

    private void halted(RsMotionHaltedEvent e) {
        if (network == null || start == null) {
            return;
        }
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            collided(Poses.of(e));
        } else {
            moveEnded(Poses.of(e));
        }
    }
}
