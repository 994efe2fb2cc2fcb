package rp1.rossum.event;

/**
 * A paint sensor's reading changed: its detector point moved onto or off floor paint of a region it
 * is sensitive to, or onto paint of another region.
 */
public class RsPaintSensorEvent extends RsSensorEvent {
    private static final long serialVersionUID = 1L;

    /** Detector position, world metres. */
    public final double x;
    /** Detector position, world metres. */
    public final double y;
    /** True if the detector is over paint of a region the sensor is sensitive to. */
    public final boolean status;
    /** Region code of the topmost paint under the detector, 0 if none. */
    public final int region;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsPaintSensorEvent(double simTime, int sensorID, double x, double y, boolean status, int region) {
        super(EVT_PAINT_SENSOR, simTime, sensorID);
        this.x = x;
        this.y = y;
        this.status = status;
        this.region = region;
    }
}
