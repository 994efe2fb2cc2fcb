package rp1.rossum.request;

import java.io.Serializable;

/**
 * Something a client asks of the simulator: every request message carries one of the
 * {@code REQ_*} codes. Request objects are what the server-side {@code RsConnection} hands to its
 * request handlers; clients usually send requests through the {@code RsClient.send...} methods.
 */
public abstract class RsRequest implements Serializable, Cloneable {
    private static final long serialVersionUID = 1L;

    public static final int REQ_MAX_CODE = 13;
    public static final int REQ_ARRAY_SIZE = 14;
    public static final int REQ_TIMEOUT = 0;
    public static final int REQ_SUBSCRIPTION = 1;
    public static final int REQ_SENSOR_STATUS = 2;
    public static final int REQ_MOTION = 3;
    public static final int REQ_HALT = 4;
    public static final int REQ_POSITION = 5;
    public static final int REQ_SET_POSITION = 6;
    public static final int REQ_PLACEMENT = 7;
    public static final int REQ_TARGET_SELECTION = 8;
    public static final int REQ_PLAN = 9;
    public static final int REQ_HEARTBEAT = 10;
    public static final int REQ_PAINTER_CHANGE = 11;
    public static final int REQ_ACTUATOR_CONTROL = 12;
    public static final int REQ_ENCODER_STATUS = 13;

    /** The request code ({@code REQ_*}). */
    public final int requestID;

    public RsRequest(int requestID) {
        this.requestID = requestID;
    }

    public int getRequestID() {
        return requestID;
    }

    /** The request index; 0 except for sensor-status requests (the sensor id). */
    public int getIndex() {
        return 0;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName();
    }
}
