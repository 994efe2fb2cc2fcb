package rp1.rossum.event;

/**
 * A target sensor's reading changed: a selected target came into or left its field of view, or moved
 * into another range or bearing bin, or a different target became the nearest.
 */
public class RsTargetSensorEvent extends RsSensorEvent {
    private static final long serialVersionUID = 1L;

    /** Detector position, world metres. */
    public final double x;
    /** Detector position, world metres. */
    public final double y;
    /** Unit vector of the line of sight, world coordinates. */
    public final double ux;
    /** Unit vector of the line of sight, world coordinates. */
    public final double uy;
    /** True if a target is detected. */
    public final boolean status;
    /** Target position along the line of sight ({@code range * cos(bearing)}), 0 when not detected. */
    public final double xDetection;
    /** Target position across the line of sight ({@code range * sin(bearing)}), 0 when not detected. */
    public final double yDetection;
    /** Distance to the target in metres, 0 when not detected. */
    public final double range;
    /** Angle from the line of sight to the target, radians, positive to the left; 0 when not detected. */
    public final double bearing;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them. No object name is reported.
     */
    public RsTargetSensorEvent(double simTime, int sensorID, double x, double y, double ux, double uy,
                               boolean status, double xDetection, double yDetection, double range, double bearing) {
        this(simTime, sensorID, x, y, ux, uy, status, xDetection, yDetection, range, bearing, null);
    }

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsTargetSensorEvent(double simTime, int sensorID, double x, double y, double ux, double uy,
                               boolean status, double xDetection, double yDetection, double range, double bearing,
                               String nameOfObjectDetected) {
        super(EVT_TARGET_SENSOR, simTime, sensorID, nameOfObjectDetected);
        this.x = x;
        this.y = y;
        this.ux = ux;
        this.uy = uy;
        this.status = status;
        this.xDetection = xDetection;
        this.yDetection = yDetection;
        this.range = range;
        this.bearing = bearing;
    }
}
