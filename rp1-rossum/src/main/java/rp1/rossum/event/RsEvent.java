package rp1.rossum.event;

import java.io.Serializable;

/**
 * Something the simulator tells a client: every message from server to client is an event. The
 * {@code EVT_*} constants are the event codes on the wire. An event carries the simulation time at
 * which it happened; handlers registered for it run in registration order until one calls
 * {@link #consume()}.
 */
public abstract class RsEvent implements Serializable, Cloneable {
    private static final long serialVersionUID = 1L;

    public static final int EVT_MAX_CODE = 13;
    public static final int EVT_ARRAY_SIZE = 14;
    public static final int EVT_CONTACT_SENSOR = 0;
    public static final int EVT_MOUSE_CLICK = 1;
    public static final int EVT_POSITION = 2;
    public static final int EVT_RANGE_SENSOR = 3;
    public static final int EVT_TARGET_SENSOR = 4;
    public static final int EVT_TIMEOUT = 5;
    public static final int EVT_MOTION_STARTED = 6;
    public static final int EVT_MOTION_HALTED = 7;
    public static final int EVT_PLACEMENT = 8;
    public static final int EVT_TARGET_SELECTION = 9;
    public static final int EVT_PLAN = 10;
    public static final int EVT_PAINT_SENSOR = 11;
    public static final int EVT_HEARTBEAT = 12;
    public static final int EVT_ENCODER_STATUS = 13;

    /** The event code ({@code EVT_*}). */
    public final int eventID;
    /** Simulation time of the event, in seconds. */
    public final double simTime;
    protected boolean consumed;

    public RsEvent(int eventID, double simTime) {
        this.eventID = eventID;
        this.simTime = simTime;
    }

    public double getSimTime() {
        return simTime;
    }

    public int getEventID() {
        return eventID;
    }

    /** The index the event is dispatched under: 0, or the sensor id for sensor events. */
    public int getIndex() {
        return 0;
    }

    /** Stops the remaining handlers registered for this event from being called. */
    public void consume() {
        consumed = true;
    }

    public boolean isConsumed() {
        return consumed;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[t=" + simTime + "]";
    }
}
