package rp1.rossum.wire;

/**
 * The protocol's numbers in one place (docs/protocol.md sections 3, 8 and 9): the header's version and
 * size, the transaction codes, and the type codes of body parts and plan objects on the wire.
 * {@code RsProtocol}'s protected constants of RP1 0.60 are these values. Request and event codes are
 * 0.60's public constants of {@code RsRequest} and {@code RsEvent}.
 */
public final class WireCodes {
    /** The protocol version every header carries. */
    public static final int VERSION = 0;
    /** Bytes in a transaction header: version, client id, client key, sequence, transaction code. */
    public static final int HEADER_BYTES = 20;

    /** Transaction code: no transaction; never sent. */
    public static final int NULL_TRANSACTION = 0;
    /** Transaction code: the client's opening message. */
    public static final int CONNECT = 1;
    /** Transaction code: the server's answer to CONNECT. */
    public static final int ACCEPT = 2;
    /** Transaction code: an event, server to client. */
    public static final int EVENT = 3;
    /** Transaction code: a request, client to server. */
    public static final int REQUEST = 4;
    /** Transaction code: the robot's body, client to server. */
    public static final int BODY_SPECIFICATION = 5;
    /** Transaction code: an event's acknowledgement, client to server. */
    public static final int INTERLOCK = 6;
    /** The highest transaction code. */
    public static final int MAX_TRANSACTION_CODE = INTERLOCK;

    /** Body part type: a part with no wire encoding. */
    public static final int UNDEFINED_BODY_PART = 0;
    /** Body part type: a wheel system. */
    public static final int WHEEL_SYSTEM = 1;
    /** Body part type: a circle. */
    public static final int BODY_CIRCLE = 2;
    /** Body part type: a polygon shape. */
    public static final int BODY_SHAPE = 3;
    /** Body part type: a generic sensor. */
    public static final int BODY_SENSOR = 4;
    /** Body part type: a target sensor. */
    public static final int BODY_TARGET_SENSOR = 5;
    /** Body part type: a contact sensor. */
    public static final int BODY_CONTACT_SENSOR = 6;
    /** Body part type: a range sensor. */
    public static final int BODY_RANGE_SENSOR = 7;
    /** Body part type: a paint sensor. */
    public static final int BODY_PAINT_SENSOR = 8;
    /** Body part type: a painter. */
    public static final int BODY_PAINTER = 9;

    /** A body part slot that is empty: its id is this and nothing follows it. */
    public static final int EMPTY_SLOT = -1;
    /** Wheel system type: differential steering. */
    public static final int DIFFERENTIAL = 0;
    /** Wheel system type: Ackerman steering. */
    public static final int ACKERMAN = 1;
    /** Wheel type: a plain wheel. */
    public static final int PLAIN_WHEEL = 0;
    /** Wheel type: a caster. */
    public static final int CASTER = 1;

    /** Plan object type: none. */
    public static final int UNDEFINED_PLAN_OBJECT = 0;
    /** Plan object type: a wall or obstacle. */
    public static final int PLAN_WALL = 1;
    /** Plan object type: a target. */
    public static final int PLAN_TARGET = 2;
    /** Plan object type: a placement. */
    public static final int PLAN_PLACEMENT = 3;
    /** Plan object type: a navigation node. */
    public static final int PLAN_NAV_NODE = 4;
    /** Plan object type: a navigation link. */
    public static final int PLAN_NAV_LINK = 5;
    /** Plan object type: floor paint. */
    public static final int PLAN_PAINT = 6;

    private WireCodes() {
    }
}
