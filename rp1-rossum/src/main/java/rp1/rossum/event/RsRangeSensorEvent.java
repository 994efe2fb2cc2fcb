package rp1.rossum.event;

/**
 * A range sensor's reading changed: it started or stopped seeing a wall within its maximum range, or
 * the distance moved into another range bin.
 */
public class RsRangeSensorEvent extends RsSensorEvent {
    private static final long serialVersionUID = 1L;

    /** Detector position, world metres. */
    public final double x;
    /** Detector position, world metres. */
    public final double y;
    /** Line of sight; always 0 from an RP1 0.60-compatible server. */
    public final double ux;
    /** Line of sight; always 0 from an RP1 0.60-compatible server. */
    public final double uy;
    /** True if a wall is within the sensor's maximum range. */
    public final boolean status;
    /** Distance to the wall in metres (0 when nothing is detected). */
    public final double range;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them. No object name is reported.
     */
    public RsRangeSensorEvent(double simTime, int sensorID, double x, double y, double ux, double uy,
                              boolean status, double range) {
        this(simTime, sensorID, x, y, ux, uy, status, range, null);
    }

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsRangeSensorEvent(double simTime, int sensorID, double x, double y, double ux, double uy,
                              boolean status, double range, String nameOfObjectDetected) {
        super(EVT_RANGE_SENSOR, simTime, sensorID, nameOfObjectDetected);
        this.x = x;
        this.y = y;
        this.ux = ux;
        this.uy = uy;
        this.status = status;
        this.range = range;
    }
}
