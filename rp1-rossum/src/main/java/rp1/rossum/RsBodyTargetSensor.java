package rp1.rossum;

import java.util.List;

import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;

/**
 * A sensor that detects targets (point sources such as candles) like a flashlight beam: a detector
 * point, a sight axis, an angular field of view (width 0 = all directions) and a maximum range. It
 * reports the nearest selected target in view that no wall hides, as range and bearing; the field of
 * view is divided into width bins and the range into range bins so that only noticeable movement
 * produces events (behavior.md section 8.2).
 *
 * <p>As in RP1 0.60 the sight axis points along the heading plus <em>twice</em> the sight angle, both
 * for detection and in the reported unit vector (a defect reproduced on purpose; harmless for a sight
 * angle of 0).
 */
public class RsBodyTargetSensor extends RsBodySensor {
    private static final long serialVersionUID = 1L;

    /** Closer than this (metres) the target counts as at the detector. */
    private static final double COINCIDENT = 1.0e-6;

    /** Detector point, body coordinates, metres. */
    protected double xDetector;
    /** Detector point, body coordinates, metres. */
    protected double yDetector;
    /** Sight angle from the heading, radians (applied twice, see the class comment). */
    protected double sightAngle;
    /** Width of the field of view, radians; 0 sees all round. */
    protected double width;
    /** Maximum range, metres. */
    protected double maxRange;
    /** Number of bearing bins across the field of view. */
    protected int nWidthBin;
    /** Number of range bins up to the maximum range. */
    protected int nRangeBin;
    /** Half the field of view, radians. */
    protected double halfWidth;
    /** Cosine of {@link #halfWidth}, for the field-of-view test. */
    protected double cosHalfWidth;
    /** Unit vector of the line of sight, world coordinates, at the last reading. */
    protected double vx;
    /** Unit vector of the line of sight, world coordinates, at the last reading. */
    protected double vy;
    /** Target position along the line of sight at the last reading, metres; 0 when none is seen. */
    protected double xTarget;
    /**
     * Target position across the line of sight at the last reading, metres; 0 when none is seen.
     */
    protected double yTarget;
    /** Distance to the target at the last reading, metres; 0 when none is seen. */
    protected double range;
    /** Bearing of the target at the last reading, radians; 0 when none is seen. */
    protected double bearing;
    /** Detector point in world coordinates at the last reading. */
    protected RsPoint mappedPos;
    /** Range bin of the last reading. */
    protected int rBin;
    /** Bearing bin of the last reading. */
    protected int wBin;
    /** Plan objects are not serializable; a copied sensor keeps only {@link #targetName}. */
    protected transient RsTarget targetDetected;
    private String targetName;

    /**
     * A target sensor.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param xDetector detector point, body coordinates
     * @param yDetector detector point, body coordinates
     * @param sightAngle direction of the sight axis relative to the heading, radians
     * @param width full angular field of view, radians (0 = omni-directional)
     * @param maxRange farthest detectable target, metres
     * @param nWidthBin number of bearing bins across the field of view
     * @param nRangeBin number of range bins up to maxRange
     */
    public RsBodyTargetSensor(double[] point, int nPoint, double xDetector, double yDetector,
                              double sightAngle, double width, double maxRange, int nWidthBin, int nRangeBin) {
        super(point, nPoint);
        this.xDetector = xDetector;
        this.yDetector = yDetector;
        this.sightAngle = sightAngle;
        this.width = width;
        this.maxRange = maxRange;
        this.nWidthBin = nWidthBin;
        this.nRangeBin = nRangeBin;
        halfWidth = width / 2.0;
        cosHalfWidth = Math.cos(halfWidth);
        name = "Unnamed Target Sensor";
    }

    /** Detector point, body coordinates. */
    public double getXDetector() {
        return xDetector;
    }

    /** Detector point, body coordinates. */
    public double getYDetector() {
        return yDetector;
    }

    /** Sight angle relative to the heading, radians (applied twice, see the class comment). */
    public double getSightAngle() {
        return sightAngle;
    }

    /** Full angular field of view, radians (0 = omni-directional). */
    public double getWidth() {
        return width;
    }

    /** Farthest detectable target, metres. */
    public double getMaxRange() {
        return maxRange;
    }

    /** Number of bearing bins across the field of view. */
    public int getNWidthBin() {
        return nWidthBin;
    }

    /** Number of range bins up to the maximum range. */
    public int getNRangeBin() {
        return nRangeBin;
    }

    /** The current range bin (meaningful while hot). */
    public int getRangeBin() {
        return rBin;
    }

    /** The current width (bearing) bin (meaningful while hot). */
    public int getWidthBin() {
        return wBin;
    }

    /** Name of the detected target, or null. */
    public String getTargetName() {
        return targetName;
    }

    /**
     * Looks for the nearest selected target of {@code plan} in view from the detector at {@code pose}
     * (behavior.md section 8.2). A change is: detecting after not detecting, another target, another
     * range or width bin, or losing the detection.
     */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsTransform pose) {
        return computeAndSetState(simTime, plan, wallsOf(plan), pose);
    }

    /** Targets of {@code plan} are sought; {@code walls} (the plan's walls, and in the simulator other robots) hide them. */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsWall[] walls, RsTransform pose) {
        mappedPos = pose.map(xDetector, yDetector);
        // Twice the sight angle: RP1 0.60 applied it twice, and clients saw that (behavior.md 8.2, 12).
        look(pose, 2.0 * sightAngle);
        vx = lookCos;
        vy = lookSin;
        boolean wasHot = hot;
        RsTarget previous = targetDetected;
        String previousName = targetName;
        int previousRBin = rBin;
        int previousWBin = wBin;
        clearDetection();
        if (plan != null) {
            search(plan, walls == null ? new RsWall[0] : walls);
        }
        boolean changed = hot
                ? !wasHot || rBin != previousRBin || wBin != previousWBin || !sameTarget(previous, previousName)
                : wasHot;
        return recordEvaluation(simTime, changed);
    }

    private boolean sameTarget(RsTarget previous, String previousName) {
        if (previous != null) {
            return previous == targetDetected;
        }
        return previousName != null && previousName.equals(targetName);
    }

    private void clearDetection() {
        hot = false;
        targetDetected = null;
        targetName = null;
        xTarget = 0.0;
        yTarget = 0.0;
        range = 0.0;
        bearing = 0.0;
    }

    private void search(RsPlan plan, RsWall[] walls) {
        double best = Double.POSITIVE_INFINITY;
        List<RsTarget> targets = plan.targets();
        for (int i = 0; i < targets.size(); i++) {
            RsTarget target = targets.get(i);
            if (!target.getSelected() || !target.isGeometrySet) {
                continue;
            }
            double dx = target.x - mappedPos.x;
            double dy = target.y - mappedPos.y;
            double r = Math.sqrt(dx * dx + dy * dy);
            if (r > maxRange || r > best) {
                continue;
            }
            if (r < COINCIDENT) {
                accept(target, 0.0, 0.0, 0.0, 0.0, 0, 0);
                return;
            }
            double tX = dx * vx + dy * vy;
            double tY = -dx * vy + dy * vx;
            double c = tX / r;
            if (width > 0 && c < cosHalfWidth) {
                continue;
            }
            if (hidden(walls, dx, dy)) {
                continue;
            }
            double b = Math.acos(Math.max(-1.0, Math.min(1.0, c)));
            if (tY < 0) {
                b = -b;
            }
            accept(target, r, b, tX, tY, widthBin(b), rangeBinOf(r, maxRange, nRangeBin));
            best = r;
        }
    }

    private void accept(RsTarget target, double r, double b, double tX, double tY, int w, int rb) {
        hot = true;
        targetDetected = target;
        targetName = target.getName();
        range = r;
        bearing = b;
        xTarget = tX;
        yTarget = tY;
        wBin = w;
        rBin = rb;
    }

    /** Whether a wall edge crosses the line of sight from the detector to the target. */
    private boolean hidden(RsWall[] walls, double dx, double dy) {
        RsSegSect sect = new RsSegSect();
        for (RsWall wall : walls) {
            for (RsSegment edge : wall.getSegmentArray()) {
                if (sect.process(mappedPos.x, mappedPos.y, dx, dy, edge.x, edge.y, edge.v.x, edge.v.y)) {
                    return true;
                }
            }
        }
        return false;
    }

    private int widthBin(double b) {
        if (width == 0) {
            return 0;
        }
        int bin = (int) Math.floor(nWidthBin * (b + halfWidth) / width);
        return Math.max(0, Math.min(bin, nWidthBin - 1));
    }

    /**
     * The reading as a target-sensor event: detector position and sight axis always, and when hot the
     * target's offsets along and across the axis, its range and bearing and its name ("" when cold).
     */
    @Override
    public RsSensorEvent getSensorEvent(double simTime) {
        return new RsTargetSensorEvent(simTime, getID(), xOf(mappedPos), yOf(mappedPos), vx, vy, hot,
                xTarget, yTarget, range, bearing, nameOrEmpty(targetName));
    }
}
