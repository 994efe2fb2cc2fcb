package rp1.rossum;

/**
 * Motion along a circular arc about a fixed pivot at a constant rate of turn; the heading turns with
 * the path (behavior.md section 5.2 item 3). A pivot at the body origin is a turn in place.
 *
 * <p>The rate given is the actual rate of change of heading. For a reversing arc (negative linear
 * velocity) RP1 0.60 puts the pivot on the side selected by the sign of the requested rotational
 * velocity but turns the heading the opposite way; the caller passes the negated rate for it.
 */
public class RsMotionCircle extends RsMotion {
    private static final long serialVersionUID = 1L;

    private final double cx;
    private final double cy;
    private final double turnRate;

    /**
     * An arc.
     *
     * @param previous the motion this one follows (its pose at startTime is the start pose), or null
     * @param startTime simulation time of the start, seconds
     * @param duration seconds
     * @param pivot the centre of the turn, world coordinates
     * @param turnRate rate of change of heading, rad/s (positive = counter-clockwise)
     */
    public RsMotionCircle(RsMotion previous, double startTime, double duration, RsPoint pivot, double turnRate) {
        super(previous, startTime, duration);
        cx = pivot.x;
        cy = pivot.y;
        this.turnRate = turnRate;
        setSignificantDeltaT(getVelocity(), turnRate);
    }

    /** The centre of the turn, world coordinates. */
    public RsPoint getPivot() {
        return new RsPoint(cx, cy);
    }

    @Override
    protected void applyTime() {
        transform = getStateAtTime(time);
    }

    /** The start pose rotated about the pivot by rate times elapsed time (position and heading). */
    @Override
    protected RsTransform getStateAtTime(double t) {
        return poseInNewTransform(t);
    }

    /**
     * {@link RsTransform#rotationAbout} the pivot, then the start pose, in place: the rotation's
     * elements are the ones {@code rotationAbout} sets (its cosine and sine of the angle, once) and the
     * product is {@link RsTransform#concat}'s, term for term, so the pose is the same to the bit.
     */
    @Override
    public void getPoseAtTime(double t, RsTransform into) {
        double angle = turnRate * (clamp(t) - time0);
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        RsTransform b = transform0;
        double a11 = c;
        double a12 = -s;
        double a13 = cx - (c * cx - s * cy);
        double a21 = s;
        double a22 = c;
        double a23 = cy - (s * cx + c * cy);
        double n11 = a11 * b.m11 + a12 * b.m21;
        double n12 = a11 * b.m12 + a12 * b.m22;
        double n13 = a11 * b.m13 + a12 * b.m23 + a13;
        double n21 = a21 * b.m11 + a22 * b.m21;
        double n22 = a21 * b.m12 + a22 * b.m22;
        double n23 = a21 * b.m13 + a22 * b.m23 + a23;
        into.m11 = n11;
        into.m12 = n12;
        into.m13 = n13;
        into.m21 = n21;
        into.m22 = n22;
        into.m23 = n23;
    }

    @Override
    public double getTurnRate() {
        return turnRate;
    }

    /**
     * Distance from the pivot to the body origin times the turn rate: its sign follows the rate of
     * turn, not the direction of travel (a forward right turn reports a negative velocity), as in
     * RP1 0.60.
     */
    @Override
    public double getVelocity() {
        double dx = transform0.m13 - cx;
        double dy = transform0.m23 - cy;
        return Math.sqrt(dx * dx + dy * dy) * turnRate;
    }

    @Override
    public RsMotionDepiction getMotionDepictionAtBodyPoint(double x, double y) {
        RsPoint p = transform.map(x, y);
        RsVector v = new RsVector(-turnRate * (p.y - cy), turnRate * (p.x - cx));
        return new RsMotionDepiction(time, p, v, transform.getTheta(), time < time1);
    }

    /**
     * Turns the body vertices about the pivot against the wall edges, and the wall vertices the
     * opposite way against the body edges, over the whole arc (at most one revolution).
     */
    @Override
    public boolean processCollision(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return recordContact(contactTime(body, nBody, walls, nWalls));
    }

    @Override
    double contactTime(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return timeTotal * SweptContact.arc(body, nBody, walls, nWalls, cx, cy, turnRate * timeTotal);
    }

    /**
     * Cuts the arc at the predicted contact (see {@link RsMotion#truncateForCollision}). Declared
     * here, as in RP1 0.60's API, so that the class keeps the original's member list.
     */
    @Override
    public void truncateForCollision() {
        super.truncateForCollision();
    }

    /** Ends the arc at {@code t}; the path up to then is unchanged. */
    @Override
    public void stopMotionAtTime(double t) {
        super.stopMotionAtTime(t);
    }
}
