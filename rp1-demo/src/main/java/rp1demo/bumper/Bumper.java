package rp1demo.bumper;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsClient;
import rp1.rossum.RsRunnable;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1demo.Standalone;
import rp1demo.clientzero.ClientZero;

/**
 * A ClientZero that asks to be placed at a random free pose ({@code "$random"}), then drives straight
 * ahead; when it bumps into something it backs off, turns and drives on. The turns grow by a
 * golden-ratio step from one bump to the next, so the car does not bounce between two walls for
 * ever. A motion that cannot even start (halted at once, with duration 0) counts as a bump; if it
 * cannot turn either, it waits a moment and turns the other way, so simulated time always moves on.
 * A placement refused (no free pose found) is asked for again after the same moment, and after
 * {@link #MOST_REFUSALS} refusals the Bumper leaves: asking again at once would hold the clock at 0.
 * It decides from its events alone, so a run is a function of the server's seed. Its body is named
 * "Bumper"; its forward speed is the run's parameter {@code param.speed} (m/s) if the server's
 * properties give one, else {@link #SPEED}, so a sweep can compare speeds ({@code --vary param.speed=0.3,0.5}).
 */
public class Bumper extends RsClient implements RsRunnable {
    /** Forward speed unless {@code param.speed} says otherwise, metres per second. */
    static final double SPEED = 0.3;
    /** How long one straight run may last before it is renewed, seconds. */
    static final double STRAIGHT = 30.0;
    /** Backing off after a bump: speed (m/s) and duration (s). */
    static final double BACK_SPEED = -0.15;
    static final double BACK_TIME = 0.5;
    /** Turning rate, radians per second. */
    static final double TURN_RATE = Math.PI / 2.0;
    /** How long it waits when it can neither go on nor turn, or was not placed, seconds. */
    static final double PAUSE = 0.25;
    /** Refused placements after which it gives up and leaves. */
    static final int MOST_REFUSALS = 40;

    private enum Doing { PLACING, AHEAD, BACKING, TURNING, WAITING }

    private RsBody body;
    private Doing doing = Doing.PLACING;
    private int refusals;
    private int bumps;
    private double turnSign = 1.0;
    private double speed = SPEED;

    /** Connects to a simulator on the network and runs until it goes away. */
    public static void main(String[] args) {
        Standalone.run(new Bumper());
    }

    /** Sends the body (with a green pen), and asks for a random free pose. */
    @Override
    public void initialize() throws IOException {
        super.initialize();
        String given = getRunParameter("speed");
        if (given != null) {
            speed = Double.parseDouble(given);
        }
        body = ClientZero.buildWithPainter(new Color(0, 140, 60));
        body.name = "Bumper";
        sendBodySpecification(body);
        addPlacementEventHandler(this::placed);
        addMotionHaltedEventHandler(this::halted);
        addTimeoutEventHandler(e -> waited());
        sendPlacementRequest("$random");
    }

    private synchronized void placed(RsPlacementEvent e) {
        if (!e.valid) {
            if (++refusals >= MOST_REFUSALS) {
                shutdown();
            } else {
                sendTimeoutRequest(PAUSE);
            }
            return;
        }
        sendPainterActivationRequest((RsBodyPainter) body.getPartByName(ClientZero.PEN));
        ahead();
    }

    private synchronized void halted(RsMotionHaltedEvent e) {
        if (e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_REQUEST) {
            return;
        }
        boolean blocked = e.causeOfHalt == RsMotionHaltedEvent.HALTED_ON_COLLISION || e.duration == 0.0;
        switch (doing) {
            case AHEAD -> {
                if (blocked) {
                    bumps++;
                    move(Doing.BACKING, BACK_SPEED, 0.0, BACK_TIME);
                } else {
                    ahead();
                }
            }
            case BACKING -> turn();
            case TURNING -> {
                if (blocked) {
                    doing = Doing.WAITING;
                    sendTimeoutRequest(PAUSE);
                } else {
                    ahead();
                }
            }
            case PLACING, WAITING -> { }
        }
    }

    /** The pause is over: ask for a place again, or turn the other way. */
    private synchronized void waited() {
        if (doing == Doing.PLACING) {
            sendPlacementRequest("$random");
            return;
        }
        turnSign = -turnSign;
        turn();
    }

    private void ahead() {
        move(Doing.AHEAD, speed, 0.0, STRAIGHT);
    }

    /** Between a quarter and three quarters of a turn, a golden-ratio step further each bump. */
    private void turn() {
        double angle = Math.PI * (0.5 + (bumps * 0.6180339887) % 1.0);
        move(Doing.TURNING, 0.0, turnSign * TURN_RATE, angle / TURN_RATE);
    }

    private void move(Doing next, double v, double w, double duration) {
        doing = next;
        sendMotionRequest(new RsMotionRequest(v, w, duration));
    }
}
