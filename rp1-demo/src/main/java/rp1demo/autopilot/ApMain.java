package rp1demo.autopilot;

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
import rp1demo.adapter.MoveRequests;
import rp1demo.adapter.NavPlans;
import rp1demo.adapter.Poses;
import rp1demo.clientzero.ClientZero;
import rp1demo.navigation.Move;
import rp1demo.navigation.Pose;

/**
 * The autopilot demo's connection to the simulator: it asks for the floor plan (for its navigation
 * network) and the "home" placement, then hands every finished move to the {@link Tour} and sends
 * the move it answers with, drawing its route with a blue trail.
 */
public class ApMain extends RsClient implements RsRunnable {
    /** Straight-line speed, metres per second. */
    public static final double SPEED = 0.3;
    /** Turning rate, radians per second (a quarter turn a second). */
    public static final double TURN_RATE = Math.PI / 2.0;

    private final MoveRequests moves = new MoveRequests(SPEED, TURN_RATE);
    private RsBody body;
    private volatile Tour tour;
    private Pose placedAt;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     *
     * @throws IOException if the simulator cannot be reached
     */
    public static void main(String[] args) throws IOException {
        ApMain c = new ApMain();
        c.initialize();
        c.run();
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public ApMain() {
        super();
    }

    @Override
    public void initialize() throws IOException {
        super.initialize();
        body = ClientZero.buildWithPainter(Color.blue);
        sendBodySpecification(body);
        addPlanEventHandler(this::planReceived);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        sendPlanRequest();
        sendPlacementRequest("home");
    }

    public RsBody getBody() {
        return body;
    }

    /** The tour, once the floor plan has arrived (else null). */
    public Tour getTour() {
        return tour;
    }

    private void planReceived(RsPlanEvent e) {
        if (e.plan instanceof RsPlan plan) {
            tour = new Tour(NavPlans.network(plan), this::log);
            begin();
        }
    }

    private void placed(RsPlacementEvent e) {
        if (!e.valid) {
            log("Placement \"" + e.name + "\" failed; the autopilot stays put");
            return;
        }
        placedAt = Poses.of(e);
        sendPainterActivationRequest((RsBodyPainter) body.getPartByName(ClientZero.PEN));
        begin();
    }

    /** Starts the tour once both the plan and the placement have come, whichever came first. */
    private void begin() {
        if (tour != null && placedAt != null) {
            drive(tour.start(placedAt), placedAt);
        }
    }

    private void halted(RsMotionHaltedEvent e) {
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION) {
            log("Ran into a wall at " + Poses.of(e) + "; the tour is abandoned");
            return;
        }
        Pose at = Poses.of(e);
        drive(tour.moveDone(at), at);
    }

    /** Sends the move, or with none left reports that the robot is parked at {@code at}. */
    private void drive(Move m, Pose at) {
        if (m == null) {
            log("Parked at " + at);
            return;
        }
        sendMotionRequest(moves.toRequest(m));
    }
}
