package rp1.rossum.event;

/**
 * A contact sensor (bumper) changed state: it touched a wall at the end of a motion that collided
 * ({@code status} true, with the wall's name), or it was released when a new motion started
 * ({@code status} false).
 */
public class RsContactSensorEvent extends RsSensorEvent {
    private static final long serialVersionUID = 1L;

    /** True while the sensor is in contact. */
    public final boolean status;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them. No object name is reported.
     */
    public RsContactSensorEvent(double simTime, int sensorID, boolean status) {
        this(simTime, sensorID, status, null);
    }

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsContactSensorEvent(double simTime, int sensorID, boolean status, String nameOfObjectDetected) {
        super(EVT_CONTACT_SENSOR, simTime, sensorID, nameOfObjectDetected);
        this.status = status;
    }
}
