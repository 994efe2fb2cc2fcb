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

    /** The highest event code. */
    public static final int EVT_MAX_CODE = 13;
    /** The number of event codes, for tables indexed by code. */
    public static final int EVT_ARRAY_SIZE = 14;
    /** A contact sensor touched or stopped touching something (docs/protocol.md section 7.1). */
    public static final int EVT_CONTACT_SENSOR = 0;
    /** A click on the simulator's floor plan (docs/protocol.md section 7.2). */
    public static final int EVT_MOUSE_CLICK = 1;
    /** Where the robot is (docs/protocol.md section 7.3). */
    public static final int EVT_POSITION = 2;
    /** A range sensor's reading (docs/protocol.md section 7.4). */
    public static final int EVT_RANGE_SENSOR = 3;
    /** A target sensor's reading (docs/protocol.md section 7.5). */
    public static final int EVT_TARGET_SENSOR = 4;
    /** A requested timeout fell due (docs/protocol.md section 7.6). */
    public static final int EVT_TIMEOUT = 5;
    /** A motion began (docs/protocol.md section 7.7). */
    public static final int EVT_MOTION_STARTED = 6;
    /** A motion ended (docs/protocol.md section 7.8). */
    public static final int EVT_MOTION_HALTED = 7;
    /** The outcome of a placement request (docs/protocol.md section 7.9). */
    public static final int EVT_PLACEMENT = 8;
    /** A target's selection state after a selection request (docs/protocol.md section 7.10). */
    public static final int EVT_TARGET_SELECTION = 9;
    /** The floor plan (docs/protocol.md section 7.11). */
    public static final int EVT_PLAN = 10;
    /** A paint sensor's reading (docs/protocol.md section 7.12). */
    public static final int EVT_PAINT_SENSOR = 11;
    /** One beat of a requested heartbeat (docs/protocol.md section 7.13). */
    public static final int EVT_HEARTBEAT = 12;
    /** An encoder's reading (docs/protocol.md section 7.14). */
    public static final int EVT_ENCODER_STATUS = 13;

    /** The event code ({@code EVT_*}). */
    public final int eventID;
    /** Simulation time of the event, in seconds. */
    public final double simTime;
    /** Set by {@link #consume()}: the remaining handlers are not called. */
    protected boolean consumed;

    /**
     * An event of the given code at the given simulation time.
     *
     * @param eventID the event code ({@code EVT_*})
     * @param simTime simulation time of the event, in seconds
     */
    public RsEvent(int eventID, double simTime) {
        this.eventID = eventID;
        this.simTime = simTime;
    }

    /**
     * Simulation time of the event, in seconds.
     *
     * @return {@link #simTime}
     */
    public double getSimTime() {
        return simTime;
    }

    /**
     * The event code.
     *
     * @return {@link #eventID}, one of the {@code EVT_*} constants
     */
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

    /**
     * Whether a handler has {@link #consume() consumed} the event.
     *
     * @return whether the remaining handlers will be skipped
     */
    public boolean isConsumed() {
        return consumed;
    }

    /** The event class and its time, for logs. */
    @Override
    public String toString() {
        return getClass().getSimpleName() + "[t=" + simTime + "]";
    }
}
