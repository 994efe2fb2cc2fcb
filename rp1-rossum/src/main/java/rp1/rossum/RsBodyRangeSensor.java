package rp1.rossum;

import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsSensorEvent;

/**
 * A range (or proximity) sensor: a ray from the detector point along the heading plus the sight
 * angle, up to the maximum range, that reports the distance to the first wall or obstacle it meets.
 * The range is divided into bins; moving within a bin is not a change (behavior.md section 8.3).
 * Targets, paint and other robots are invisible to it.
 */
public class RsBodyRangeSensor extends RsBodySensor {
    private static final long serialVersionUID = 1L;

    /** Larger maximum ranges are reduced to this (metres). */
    static final double MAX_MAX_RANGE = 1.0e6;

    /** Detector point, body coordinates, metres. */
    protected double xDetector;
    /** Detector point, body coordinates, metres. */
    protected double yDetector;
    /** Sight direction relative to the heading, radians. */
    protected double sightAngle;
    /** Maximum range, metres. */
    protected double maxRange;
    /** Number of range bins up to the maximum range. */
    protected int nRangeBin;
    /**
     * Line-of-sight vector. RP1 0.60 never stores it, so events carry ux = uy = 0; these stay 0 for
     * the same reason.
     */
    protected double vx;
    /** Line-of-sight vector; see {@link #vx}. */
    protected double vy;
    /** Distance to the wall seen at the last reading, metres; 0 when none is. */
    protected double range;
    /** Detector point in world coordinates at the last reading. */
    protected RsPoint mappedPos;
    /** Range bin of the last reading; -1 before the first. */
    protected int rBin = -1;
    /** Plan objects are not serializable; a copied sensor keeps only {@link #objectName}. */
    protected transient RsObject objectDetected;
    private String objectName;

    /**
     * A range sensor.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param xDetector detector point, body coordinates
     * @param yDetector detector point, body coordinates
     * @param sightAngle direction of the ray relative to the heading, radians
     * @param maxRange length of the ray, metres (values above 1e6 become 1e6)
     * @param nRangeBin number of range bins (values below 1 become 1)
     */
    public RsBodyRangeSensor(double[] point, int nPoint, double xDetector, double yDetector,
                             double sightAngle, double maxRange, int nRangeBin) {
        super(point, nPoint);
        this.xDetector = xDetector;
        this.yDetector = yDetector;
        this.sightAngle = sightAngle;
        this.maxRange = Math.min(maxRange, MAX_MAX_RANGE);
        this.nRangeBin = Math.max(1, nRangeBin);
        name = "Unnamed Range Sensor";
    }

    /** Detector point, body coordinates. */
    public double getXDetector() {
        return xDetector;
    }

    /** Detector point, body coordinates. */
    public double getYDetector() {
        return yDetector;
    }

    /** Direction of the ray relative to the heading, radians. */
    public double getSightAngle() {
        return sightAngle;
    }

    /** Length of the ray in metres, after clamping to 1e6. */
    public double getMaxRange() {
        return maxRange;
    }

    /** Number of range bins, at least 1. */
    public int getNRangeBin() {
        return nRangeBin;
    }

    /** The current range bin; -1 before the first detection. */
    public int getRangeBin() {
        return rBin;
    }

    /** The current range (0 when nothing is detected). */
    public double getRange() {
        return range;
    }

    /**
     * Casts the ray against every wall edge. A hit closer than maxRange is a detection (a hit at
     * exactly maxRange is not). A change is: detecting after not detecting, another range bin, or
     * losing the detection.
     */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsTransform pose) {
        return computeAndSetState(simTime, plan, wallsOf(plan), pose);
    }

    /** The ray is cast against {@code walls}: the plan's walls and, in the simulator, other robots. */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsWall[] walls, RsTransform pose) {
        mappedPos = pose.map(xDetector, yDetector);
        look(pose, sightAngle);
        double dx = maxRange * lookCos;
        double dy = maxRange * lookSin;
        boolean wasHot = hot;
        int previousBin = rBin;
        double nearest = 1.0;
        RsWall nearestWall = null;
        if (walls != null) {
            RsSegSect sect = new RsSegSect();
            for (RsWall wall : walls) {
                for (RsSegment e : wall.getSegmentArray()) {
                    if (sect.process(mappedPos.x, mappedPos.y, dx, dy, e.x, e.y, e.v.x, e.v.y) && sect.t1 < nearest) {
                        nearest = sect.t1;
                        nearestWall = wall;
                    }
                }
            }
        }
        hot = nearestWall != null;
        objectDetected = nearestWall;
        objectName = hot ? nearestWall.getName() : null;
        range = hot ? nearest * maxRange : 0.0;
        rBin = hot ? rangeBinOf(range, maxRange, nRangeBin) : previousBin;
        boolean changed = hot ? !wasHot || rBin != previousBin : wasHot;
        return recordEvaluation(simTime, changed);
    }

    /** The reading as a range-sensor event (ux = uy = 0, as RP1 0.60 sends them; name "" when cold). */
    @Override
    public RsSensorEvent getSensorEvent(double simTime) {
        return new RsRangeSensorEvent(simTime, getID(), xOf(mappedPos), yOf(mappedPos), vx, vy, hot, range,
                nameOrEmpty(objectName));
    }
}
