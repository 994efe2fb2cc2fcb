package rp1.rossum;

import java.util.Arrays;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsSensorEvent;

/**
 * A sensor for floor paint at a single detector point (for line followers, slippery patches, ...).
 * It reports the region code of the topmost paint under the point and is hot when that region is one
 * it is sensitive to (behavior.md section 8.4). Without a sensitivity list it is sensitive to every
 * region.
 */
public class RsBodyPaintSensor extends RsBodySensor {
    private static final long serialVersionUID = 1L;

    /** Detector point, body coordinates, metres. */
    protected double xDetector;
    /** Detector point, body coordinates, metres. */
    protected double yDetector;
    /** Detector point in world coordinates at the last reading. */
    protected RsPoint mappedPos;
    /** Region code of the paint under the detector at the last reading; 0 for none. */
    protected int region;
    /** Region codes the sensor is sensitive to; null = every region. */
    protected int[] regionSensitivity;

    /**
     * A paint sensor.
     *
     * @param point outline x0, y0, x1, y1, ... (body coordinates)
     * @param nPoint number of outline points
     * @param xDetector detector point, body coordinates
     * @param yDetector detector point, body coordinates
     */
    public RsBodyPaintSensor(double[] point, int nPoint, double xDetector, double yDetector) {
        super(point, nPoint);
        this.xDetector = xDetector;
        this.yDetector = yDetector;
        name = "Unnamed Paint Sensor";
    }

    /** Detector point, body coordinates. */
    public double getXDetector() {
        return xDetector;
    }

    /** Detector point, body coordinates. */
    public double getYDetector() {
        return yDetector;
    }

    /** The region under the detector at the last evaluation (0 = no paint). */
    public int getRegion() {
        return region;
    }

    /** A copy of the sensitivity list, or null when the sensor is sensitive to every region. */
    public int[] getRegionSensitivity() {
        return regionSensitivity == null ? null : regionSensitivity.clone();
    }

    /** Makes the sensor sensitive to this one region only. */
    public void setRegionSensitivity(int region) {
        regionSensitivity = new int[] {region};
    }

    /**
     * Makes the sensor sensitive to these regions only; null or an empty array means every region
     * (an empty list is sent as "no list", which the simulator has always read as every region).
     */
    public void setRegionSensitivity(int[] regions) {
        regionSensitivity = regions == null || regions.length == 0 ? null : regions.clone();
    }

    /**
     * Finds the topmost paint (the last declared) that strictly contains the detector point. A change
     * is a change of status, or of region.
     */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsTransform pose) {
        mappedPos = pose.map(xDetector, yDetector);
        boolean wasHot = hot;
        int previousRegion = region;
        region = 0;
        hot = false;
        RsPaint paint = plan == null ? null : topmostPaintAt(plan, mappedPos.x, mappedPos.y);
        if (paint != null) {
            region = paint.getRegion();
            hot = isSensitiveTo(region);
        }
        boolean changed = hot ? !wasHot || region != previousRegion : wasHot || region != previousRegion;
        return recordEvaluation(simTime, changed);
    }

    private static RsPaint topmostPaintAt(RsPlan plan, double x, double y) {
        RsPaint[] paints = plan.getPaintArray();
        for (int i = paints.length - 1; i >= 0; i--) {
            RsPolygon p = paints[i].getPolygon();
            if (p != null && p.checkContainment(x, y) == RsPolygon.INSIDE) {
                return paints[i];
            }
        }
        return null;
    }

    private boolean isSensitiveTo(int code) {
        return regionSensitivity == null || Arrays.stream(regionSensitivity).anyMatch(r -> r == code);
    }

    /** The reading as a paint-sensor event: detector position, status and region. */
    @Override
    public RsSensorEvent getSensorEvent(double simTime) {
        return new RsPaintSensorEvent(simTime, getID(), xOf(mappedPos), yOf(mappedPos), hot, region);
    }
}
