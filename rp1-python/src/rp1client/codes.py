"""Numbers of the RP1 wire protocol (docs/protocol.md sections 3, 5, 8, 9 and 12), kept in one place."""

VERSION = 0

# Transaction codes (protocol.md section 3.1).
CONNECT = 1
ACCEPT = 2
EVENT = 3
REQUEST = 4
BODY_SPECIFICATION = 5
INTERLOCK = 6
TRANSACTION_NAMES = ("NULL", "CONNECT", "ACCEPT", "EVENT", "REQUEST", "BODY_SPECIFICATION", "INTERLOCK")

# Request codes (section 5.1).
REQ_TIMEOUT = 0
REQ_SUBSCRIPTION = 1
REQ_SENSOR_STATUS = 2
REQ_MOTION = 3
REQ_HALT = 4
REQ_POSITION = 5
REQ_SET_POSITION = 6
REQ_PLACEMENT = 7
REQ_TARGET_SELECTION = 8
REQ_PLAN = 9
REQ_HEARTBEAT = 10
REQ_PAINTER_CHANGE = 11
REQ_ACTUATOR_CONTROL = 12
REQ_ENCODER_STATUS = 13
REQ_MAX_CODE = 13

# Event codes (section 5.2).
EVT_CONTACT_SENSOR = 0
EVT_MOUSE_CLICK = 1
EVT_POSITION = 2
EVT_RANGE_SENSOR = 3
EVT_TARGET_SENSOR = 4
EVT_TIMEOUT = 5
EVT_MOTION_STARTED = 6
EVT_MOTION_HALTED = 7
EVT_PLACEMENT = 8
EVT_TARGET_SELECTION = 9
EVT_PLAN = 10
EVT_PAINT_SENSOR = 11
EVT_HEARTBEAT = 12
EVT_ENCODER_STATUS = 13
EVT_MAX_CODE = 13

#: Events the simulation generates on its own; a client gets them only when subscribed (section 10).
SUBSCRIBED_EVENTS = frozenset({
    EVT_MOUSE_CLICK, EVT_MOTION_STARTED, EVT_MOTION_HALTED,
    EVT_CONTACT_SENSOR, EVT_RANGE_SENSOR, EVT_TARGET_SENSOR, EVT_PAINT_SENSOR,
})

# Body part types (section 8.2).
PART_UNDEFINED = 0
PART_WHEEL_SYSTEM = 1
PART_CIRCLE = 2
PART_SHAPE = 3
PART_ABSTRACT_SENSOR = 4
PART_TARGET_SENSOR = 5
PART_CONTACT_SENSOR = 6
PART_RANGE_SENSOR = 7
PART_PAINT_SENSOR = 8
PART_PAINTER = 9
EMPTY_PART_SLOT = -1

# Plan object types (section 9).
PLAN_WALL = 1
PLAN_TARGET = 2
PLAN_PLACEMENT = 3
PLAN_NAV_NODE = 4
PLAN_NAV_LINK = 5
PLAN_PAINT = 6

# Counts a peer may announce (section 12); checked before anything is allocated.
MAX_BODY_PARTS = 4096
MAX_OUTLINE_VERTICES = 65536
MAX_WHEELS = 256
MAX_REGIONS = 4096
MAX_PLAN_OBJECTS = 1 << 20
MAX_GEOMETRY_DOUBLES = 1 << 20
MAX_COLORS = 4096
MAX_ACTUATOR_PARAMETERS = 1024
MAX_ENCODERS = 4096
#: The longest message the client waits for the rest of, as the Java library's buffering reader
#: (``WireLimits.MAX_MESSAGE_BYTES``): the bytes held for one message stay bounded whatever a peer sends.
MAX_MESSAGE_BYTES = 4 << 20


def describe_transaction(code: int) -> str:
    """``NAME (code)`` for a known transaction code, else the bare number."""
    if 0 <= code < len(TRANSACTION_NAMES):
        return f"{TRANSACTION_NAMES[code]} ({code})"
    return str(code)
