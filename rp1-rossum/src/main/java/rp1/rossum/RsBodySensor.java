package rp1.rossum;

import java.awt.Color;
import rp1.rossum.event.RsSensorEvent;

/**
 * A body shape that senses something: a target, range, paint or contact sensor. A sensor is "hot"
 * while it detects something (drawn in its hot colours; the default hot line colour is red). The
 * simulator evaluates it at motion steps; {@link #didStateChange()} says whether the last evaluation
 * changed what a client would be told, and {@link #getSensorEvent(double)} builds that report.
 */
public abstract class RsBodySensor extends RsBodyShape {
    private static final long serialVersionUID = 1L;

    /** Red, the default hot line colour of sensors. */
    static final Color DEFAULT_HOT_LINE_COLOR = new Color(255, 0, 0);

    /** Whether the last reading changed the sensor's state (an event is due). */
    protected boolean stateChange;
    /** Simulation time of the last reading, seconds. */
    protected double timeStateComputed;
    /** Whether {@link #lookCos} and {@link #lookSin} hold the direction for the rotation and offset below. */
    private transient boolean lookKnown;
    private transient double lookM11;
    private transient double lookM21;
    private transient double lookOffset;
    /** The cosine and sine of the direction {@link #look} worked out last. */
    transient double lookCos;
    transient double lookSin;

    /** A sensor with the given outline (see {@link RsBodyShape#RsBodyShape(double[], int)}). */
    public RsBodySensor(double[] point, int nPoint) {
        super(point, nPoint);
        hotLineColor = DEFAULT_HOT_LINE_COLOR;
    }

    @Override
    public boolean isASensor() {
        return true;
    }

    /**
     * Sets {@link #lookCos} and {@link #lookSin} to {@code Math.cos} and {@code Math.sin} of the
     * heading of {@code pose} ({@link RsTransform#getTheta()}) plus {@code offset}. They are kept from
     * the last call while the pose's rotation and the offset are the same to the bit, which is the
     * case at every step of a robot driving straight or standing still: an arc tangent, a sine and a
     * cosine per sensor per step were a third of a range or target sensor's reading.
     */
    final void look(RsTransform pose, double offset) {
        if (lookKnown && RsTransform.sameBits(pose.m11, lookM11) && RsTransform.sameBits(pose.m21, lookM21)
                && RsTransform.sameBits(offset, lookOffset)) {
            return;
        }
        double heading = pose.getTheta() + offset;
        lookCos = Math.cos(heading);
        lookSin = Math.sin(heading);
        lookM11 = pose.m11;
        lookM21 = pose.m21;
        lookOffset = offset;
        lookKnown = true;
    }

    /** Whether the last {@link #computeAndSetState} changed the reportable state. */
    public boolean didStateChange() {
        return stateChange;
    }

    /** The simulation time of the last evaluation. */
    public double getTimeOfLastStateComputation() {
        return timeStateComputed;
    }

    /**
     * Evaluates the sensor at simulation time {@code simTime} with the body at {@code pose} in
     * {@code plan}, stores the new state and whether it changed.
     *
     * @return whether the state changed
     */
    public abstract boolean computeAndSetState(double simTime, RsPlan plan, RsTransform pose);

    /**
     * As {@link #computeAndSetState(double, RsPlan, RsTransform)}, with {@code walls} as what blocks the
     * sensor instead of the plan's walls (the simulator adds other robots). Sensors that walls do not
     * affect ignore it.
     */
    public boolean computeAndSetState(double simTime, RsPlan plan, RsWall[] walls, RsTransform pose) {
        return computeAndSetState(simTime, plan, pose);
    }

    /** The current state as an event stamped {@code simTime}; the base sensor has none (null). */
    public RsSensorEvent getSensorEvent(double simTime) {
        return null;
    }

    /** Records the evaluation time and change flag; returns the flag. */
    final boolean recordEvaluation(double simTime, boolean changed) {
        timeStateComputed = simTime;
        stateChange = changed;
        return changed;
    }

    @Override
    public void copyStateData(RsBodyPart source) {
        super.copyStateData(source);
        if (source instanceof RsBodySensor) {
            RsBodySensor s = (RsBodySensor) source;
            stateChange = s.stateChange;
            timeStateComputed = s.timeStateComputed;
        }
    }

    /** The x coordinate of a detector position, 0 before the first evaluation. */
    static double xOf(RsPoint detector) {
        return detector == null ? 0.0 : detector.x;
    }

    /** The y coordinate of a detector position, 0 before the first evaluation. */
    static double yOf(RsPoint detector) {
        return detector == null ? 0.0 : detector.y;
    }

    /** An empty string for null, as the wire delivers names. */
    static String nameOrEmpty(String name) {
        return name == null ? "" : name;
    }

    /** What blocks a range or target sensor's view when only the plan is given: its walls. */
    static RsWall[] wallsOf(RsPlan plan) {
        return plan == null ? null : plan.getWallArray();
    }

    /** The range bin, 0..nRangeBin - 1, of a detection at {@code range} (below {@code maxRange}). */
    static int rangeBinOf(double range, double maxRange, int nRangeBin) {
        return Math.min((int) Math.floor(nRangeBin * range / maxRange), nRangeBin - 1);
    }
}
