package rp1.rossum.request;

/** Report one sensor's current state now (polling), whatever the subscriptions. */
public class RsSensorRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /** Part id of the sensor. */
    public final int sensorID;

    /** A request with these values (the fields say what each one is). */
    public RsSensorRequest(int sensorID) {
        super(REQ_SENSOR_STATUS);
        this.sensorID = sensorID;
    }

    /** The sensor id. */
    @Override
    public int getIndex() {
        return sensorID;
    }
}
