package rp1demo.adapter;

import rp1.rossum.request.RsMotionRequest;
import rp1demo.navigation.Move;

/**
 * Motion requests for the {@link Move}s of a robot that turns on the spot (differential steering):
 * a turn at a fixed rate about the axle centre, a straight run at a fixed speed.
 */
public final class MoveRequests {
    private final double speed;
    private final double turnRate;

    /**
     * @param speed    metres per second for straight runs
     * @param turnRate radians per second for turns
     */
    public MoveRequests(double speed, double turnRate) {
        if (!(speed > 0.0) || !(turnRate > 0.0)) {
            throw new IllegalArgumentException("speed and turnRate must be positive, got " + speed + ", " + turnRate);
        }
        this.speed = speed;
        this.turnRate = turnRate;
    }

    /** The request that makes the move. */
    public RsMotionRequest toRequest(Move move) {
        if (move instanceof Move.Turn t) {
            return new RsMotionRequest(0.0, Math.copySign(turnRate, t.angle()), Math.abs(t.angle()) / turnRate);
        }
        Move.Forward f = (Move.Forward) move;
        return new RsMotionRequest(Math.copySign(speed, f.distance()), 0.0, Math.abs(f.distance()) / speed);
    }
}
