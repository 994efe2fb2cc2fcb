package rp1.rossum;

/**
 * Straight-line motion at constant velocity with constant heading: forward along the heading, or
 * backwards when the velocity is negative (behavior.md section 5.2 item 2).
 */
public class RsMotionLine extends RsMotion {
    private static final long serialVersionUID = 1L;

    private final double ux;
    private final double uy;
    private final double velocity;

    /**
     * A straight motion.
     *
     * @param previous the motion this one follows (its pose at startTime is the start pose), or null
     * @param startTime simulation time of the start, seconds
     * @param duration seconds
     * @param heading the robot's heading as a unit vector, world coordinates (the direction of
     *                forward travel; it is normalised here)
     * @param linearVelocity signed speed along the heading, m/s (negative = backing)
     */
    public RsMotionLine(RsMotion previous, double startTime, double duration, RsVector heading, double linearVelocity) {
        super(previous, startTime, duration);
        RsVector u = heading.unit();
        ux = u.x;
        uy = u.y;
        velocity = linearVelocity;
        setSignificantDeltaT(velocity, 0.0);
    }

    @Override
    protected void applyTime() {
        transform = getStateAtTime(time);
    }

    @Override
    protected RsTransform getStateAtTime(double t) {
        return poseInNewTransform(t);
    }

    @Override
    public void getPoseAtTime(double t, RsTransform into) {
        double d = velocity * (clamp(t) - time0);
        into.copy(transform0);
        into.setOffset(transform0.m13 + d * ux, transform0.m23 + d * uy);
    }

    /** The signed linear velocity: negative when travelling opposite to the heading. */
    @Override
    public double getVelocity() {
        return velocity;
    }

    @Override
    public RsMotionDepiction getMotionDepictionAtBodyPoint(double x, double y) {
        return new RsMotionDepiction(time, transform.map(x, y), new RsVector(velocity * ux, velocity * uy),
                transform.getTheta(), time < time1);
    }

    /**
     * Sweeps the body vertices along the whole displacement against the wall edges, and the wall
     * vertices along the reversed displacement against the body edges.
     */
    @Override
    public boolean processCollision(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return recordContact(contactTime(body, nBody, walls, nWalls));
    }

    @Override
    double contactTime(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return contactTime(body, nBody, walls, nWalls, null);
    }

    @Override
    boolean cannotMeetBefore(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double t) {
        return cannotMeetBefore(body, nBody, walls, nWalls, t, null);
    }

    /**
     * The body's extents along and across the displacement, which every wall's test needs: worked out
     * once per search instead of once per wall (in a crowd's arena, half the cost of testing a wall).
     */
    @Override
    double[] prepare(RsSegment[] body, int nBody) {
        if (getClass() != RsMotionLine.class) {
            return null;
        }
        double distance = velocity * timeTotal;
        return SweptContact.bodyExtents(body, nBody, distance * ux, distance * uy);
    }

    @Override
    boolean processCollision(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double[] prepared) {
        return prepared == null ? processCollision(body, nBody, walls, nWalls)
                : recordContact(contactTime(body, nBody, walls, nWalls, prepared));
    }

    @Override
    double contactTime(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double[] prepared) {
        double distance = velocity * timeTotal;
        return timeTotal * SweptContact.line(body, nBody, walls, nWalls, distance * ux, distance * uy, prepared);
    }

    @Override
    boolean cannotMeetBefore(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double t, double[] prepared) {
        double distance = velocity * timeTotal;
        return timeTotal > 0.0 && SweptContact.lineBeyond(body, nBody, walls, nWalls, distance * ux, distance * uy,
                t / timeTotal, prepared);
    }

    /**
     * Cuts the motion at the predicted contact (see {@link RsMotion#truncateForCollision}). Declared
     * here, as in RP1 0.60's API, so that the class keeps the original's member list.
     */
    @Override
    public void truncateForCollision() {
        super.truncateForCollision();
    }

    /** Ends the straight motion at {@code t}; the path up to then is unchanged. */
    @Override
    public void stopMotionAtTime(double t) {
        super.stopMotionAtTime(t);
    }
}
