package rp1.rossum;

/**
 * A motion of zero length: the robot rests at one pose. It is what a placement, a null motion
 * request (duration below 0.1 ms, or no speed) or an immediate collision produces.
 */
public class RsMotionNull extends RsMotion {
    private static final long serialVersionUID = 1L;

    /**
     * Rest where {@code previous} is at {@code time}, continuing its continuity series.
     *
     * @param previous the motion before (null = the origin, new series)
     * @param time simulation time, seconds
     */
    public RsMotionNull(RsMotion previous, double time) {
        super(previous, time, 0.0);
    }

    /**
     * Rest at a new pose (a placement), starting a new continuity series.
     *
     * @param time simulation time, seconds
     * @param x world position of the body origin, metres
     * @param y world position of the body origin, metres
     * @param orientation heading, radians
     */
    public RsMotionNull(double time, double x, double y, double orientation) {
        super(null, time, 0.0);
        transform0 = new RsTransform(orientation, x, y);
        transform = new RsTransform(transform0);
    }

    @Override
    protected void applyTime() {
        transform = getStateAtTime(time);
    }

    @Override
    protected RsTransform getStateAtTime(double t) {
        return new RsTransform(transform0);
    }

    @Override
    public void getPoseAtTime(double t, RsTransform into) {
        into.copy(transform0);
    }

    @Override
    public RsMotionDepiction getMotionDepictionAtBodyPoint(double x, double y) {
        return new RsMotionDepiction(time, transform.map(x, y), new RsVector(), transform.getTheta(), false);
    }
}
