package rp1.rossum.event;

/**
 * An event about one sensor of the robot's body: contact, range, target or paint. It is dispatched to
 * the handlers registered for that sensor, identified by the sensor's part id.
 */
public abstract class RsSensorEvent extends RsEvent {
    private static final long serialVersionUID = 1L;

    /** Part id of the sensor ({@code RsBodySensor.getID()}). */
    public final int sensorID;
    /**
     * The name of the object the sensor detected, or null (see {@link #getNameOfObjectDetected()}).
     */
    protected String nameOfObjectDetected;

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them. No object name is reported.
     */
    public RsSensorEvent(int eventID, double simTime, int sensorID) {
        this(eventID, simTime, sensorID, null);
    }

    /**
     * An event with these values (the fields say what each one is). Clients receive events; the
     * library and the server build them.
     */
    public RsSensorEvent(int eventID, double simTime, int sensorID, String nameOfObjectDetected) {
        super(eventID, simTime);
        this.sensorID = sensorID;
        this.nameOfObjectDetected = nameOfObjectDetected;
    }

    /** The sensor id: sensor events are dispatched per sensor. */
    @Override
    public int getIndex() {
        return sensorID;
    }

    /** Name of the wall, obstacle or target detected; empty (or null) when nothing is. */
    public String getNameOfObjectDetected() {
        return nameOfObjectDetected;
    }
}
