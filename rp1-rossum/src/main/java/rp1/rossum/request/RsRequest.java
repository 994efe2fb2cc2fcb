package rp1.rossum.request;

import java.io.Serializable;

/**
 * Something a client asks of the simulator: every request message carries one of the
 * {@code REQ_*} codes. Request objects are what the server-side {@code RsConnection} hands to its
 * request handlers; clients usually send requests through the {@code RsClient.send...} methods.
 */
public abstract class RsRequest implements Serializable, Cloneable {
    private static final long serialVersionUID = 1L;

    /** The highest request code. */
    public static final int REQ_MAX_CODE = 13;
    /** The number of request codes, for tables indexed by code. */
    public static final int REQ_ARRAY_SIZE = 14;
    /** A timeout event after a duration (docs/protocol.md section 6.1). */
    public static final int REQ_TIMEOUT = 0;
    /** Subscribe to or unsubscribe from a kind of event (docs/protocol.md section 6.2). */
    public static final int REQ_SUBSCRIPTION = 1;
    /** Poll one sensor (docs/protocol.md section 6.3). */
    public static final int REQ_SENSOR_STATUS = 2;
    /** Move at a velocity for a duration (docs/protocol.md section 6.4). */
    public static final int REQ_MOTION = 3;
    /** Stop the motion in progress (docs/protocol.md section 6.5). */
    public static final int REQ_HALT = 4;
    /** Report where the robot is (docs/protocol.md section 6.6). */
    public static final int REQ_POSITION = 5;
    /** Reserved: no client sends it (docs/protocol.md section 6.7). */
    public static final int REQ_SET_POSITION = 6;
    /** Place the robot (docs/protocol.md section 6.8). */
    public static final int REQ_PLACEMENT = 7;
    /** Select or deselect targets (docs/protocol.md section 6.9). */
    public static final int REQ_TARGET_SELECTION = 8;
    /** Send the floor plan (docs/protocol.md section 6.10). */
    public static final int REQ_PLAN = 9;
    /** Send heartbeat events at an interval (docs/protocol.md section 6.11). */
    public static final int REQ_HEARTBEAT = 10;
    /** Switch a painter on or off, or erase its trail (docs/protocol.md section 6.12). */
    public static final int REQ_PAINTER_CHANGE = 11;
    /** Command an actuator (docs/protocol.md section 6.13). */
    public static final int REQ_ACTUATOR_CONTROL = 12;
    /** Report wheel encoders (docs/protocol.md section 6.14). */
    public static final int REQ_ENCODER_STATUS = 13;

    /** The request code ({@code REQ_*}). */
    public final int requestID;

    /**
     * A request of the given code.
     *
     * @param requestID the request code ({@code REQ_*})
     */
    public RsRequest(int requestID) {
        this.requestID = requestID;
    }

    /**
     * The request code.
     *
     * @return {@link #requestID}, one of the {@code REQ_*} constants
     */
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
