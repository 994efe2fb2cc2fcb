package rp1demo.linetracker;

/**
 * A two-eyed line follower: both eyes on the line, drive straight; one eye off, steer back towards
 * the side still on it; both off, turn on the spot towards the side that saw the line last until an
 * eye finds it again. It decides wheel speeds from what the eyes report, nothing else, as the
 * controller of a real line-following robot would.
 */
public final class LineFollower {
    /** Which eye. */
    public enum Eye { LEFT, RIGHT }

    /**
     * Speeds of the wheels' rims.
     *
     * @param left  metres per second, negative backwards
     * @param right metres per second, negative backwards
     */
    public record WheelSpeeds(double left, double right) {
    }

    private final double cruise;
    private boolean leftOn = true;
    private boolean rightOn = true;
    private Eye lastOn = Eye.LEFT;
    private int timesLost;

    /** @param cruise wheel speed on the straight, metres per second */
    public LineFollower(double cruise) {
        if (!(cruise > 0.0)) {
            throw new IllegalArgumentException("cruise speed must be positive, got " + cruise);
        }
        this.cruise = cruise;
    }

    /** An eye saw the line appear or disappear; returns the wheel speeds to drive at now. */
    public WheelSpeeds sensed(Eye eye, boolean onLine) {
        boolean wasLost = isLost();
        if (eye == Eye.LEFT) {
            leftOn = onLine;
        } else {
            rightOn = onLine;
        }
        if (leftOn != rightOn) {
            lastOn = leftOn ? Eye.LEFT : Eye.RIGHT;
        }
        if (isLost() && !wasLost) {
            timesLost++;
        }
        return command();
    }

    /** The wheel speeds for what the eyes see now. */
    public WheelSpeeds command() {
        if (leftOn && rightOn) {
            return new WheelSpeeds(cruise, cruise);
        }
        double slow = cruise / 3.0;
        if (leftOn) {
            return new WheelSpeeds(slow, cruise);
        }
        if (rightOn) {
            return new WheelSpeeds(cruise, slow);
        }
        return lastOn == Eye.LEFT ? new WheelSpeeds(-slow, slow) : new WheelSpeeds(slow, -slow);
    }

    /** Whether neither eye sees the line. */
    public boolean isLost() {
        return !leftOn && !rightOn;
    }

    /** How many times both eyes have lost the line. */
    public int timesLost() {
        return timesLost;
    }
}
