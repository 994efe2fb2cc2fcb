package rp1.rossum;

/**
 * A free-turning caster: a wheel that swivels about its pivot (x, y) to follow its direction of
 * travel. It has radius 0 for the wire format, a steering limit of a full turn, and no encoder.
 */
public class RsWheelCaster extends RsWheel {
    private static final long serialVersionUID = 1L;

    /**
     * A caster.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param x pivot position, body coordinates
     * @param y pivot position, body coordinates
     */
    public RsWheelCaster(double[] point, int nPoint, double x, double y) {
        super(point, nPoint, x, y, 0.0, 2.0 * Math.PI);
    }

    @Override
    public boolean isWheelSteerable() {
        return true;
    }

    /** Swivels the caster to its pivot's direction of travel; a still caster keeps its angle. */
    @Override
    protected void applyMotion(RsMotion motion) {
        super.applyMotion(motion);
        double direction = motion.getMotionDepictionAtBodyPoint(getX(), getY()).getDirectionInBody();
        if (!Double.isNaN(direction)) {
            setOrientation(direction);
        }
    }
}
