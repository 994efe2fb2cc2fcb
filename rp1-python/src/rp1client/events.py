"""Events: everything the simulator tells a client (docs/protocol.md section 7).

Every event carries the simulation time it happened at. Handlers registered for an event run in
registration order until one calls :meth:`Event.consume`. Fields are listed in wire order, which is
not always the order of the Java constructors.
"""

import struct
from dataclasses import dataclass
from typing import ClassVar, Dict, Optional, Tuple, Type

from . import codes
from .errors import ProtocolError
from .plan import Plan, read_plan, write_plan
from .wire import Reader, Record, Writer, read_exactly

_PREFIX = struct.Struct(">iidi")


@dataclass
class Event:
    """Base of all events."""

    sim_time: float

    code: ClassVar[int] = -1
    record: ClassVar[Record] = Record()
    _consumed = False

    @property
    def index(self) -> int:
        """What the event is dispatched under besides its type: the sensor id, or 0."""
        return 0

    def consume(self) -> None:
        """Keeps the remaining handlers registered for this event from being called."""
        self._consumed = True

    @property
    def consumed(self) -> bool:
        return self._consumed

    @classmethod
    def _read(cls, r: Reader, sim_time: float, index: int) -> "Event":
        return cls(sim_time, **cls.record.read(r))

    def _write(self, w: Writer) -> None:
        self.record.write(w, self)


@dataclass
class SensorEvent(Event):
    """An event about one sensor of the body, dispatched to the handlers of that sensor."""

    sensor_id: int

    @property
    def index(self) -> int:
        return self.sensor_id

    @classmethod
    def _read(cls, r: Reader, sim_time: float, index: int) -> "Event":
        return cls(sim_time, index, **cls.record.read(r))


@dataclass
class ContactSensorEvent(SensorEvent):
    """A bumper touched a wall (``status`` true, with its name) or was released."""

    status: bool
    object_name: str

    code = codes.EVT_CONTACT_SENSOR
    record = Record(("?", "status", "contact sensor status"), ("s", "object_name", "contact sensor object name"))


@dataclass
class MouseClickEvent(Event):
    """A click on the simulator's view: ``button`` 0 is the primary one; ``x``, ``y`` in metres."""

    button: int
    click_count: int
    x: float
    y: float

    code = codes.EVT_MOUSE_CLICK
    record = Record(("i", "button", "mouse click button"), ("i", "click_count", "mouse click count"),
                    ("d", "x", "mouse click x"), ("d", "y", "mouse click y"))


@dataclass
class PositionEvent(Event):
    """The robot's pose (orientation in (-pi, pi]) and its current velocities."""

    x: float
    y: float
    orientation: float
    velocity: float
    turn_rate: float

    code = codes.EVT_POSITION
    record = Record(("d", "x", "position x"), ("d", "y", "position y"), ("d", "orientation", "position orientation"),
                    ("d", "velocity", "position velocity"), ("d", "turn_rate", "position turn rate"))


@dataclass
class RangeSensorEvent(SensorEvent):
    """A range reading: detector point, whether a wall is in range, the range and the wall's name.

    ``ux`` and ``uy`` are always 0, as RP1 0.60 sends them.
    """

    x: float
    y: float
    status: bool
    ux: float
    uy: float
    range: float
    object_name: str

    code = codes.EVT_RANGE_SENSOR
    record = Record(("d", "x", "range sensor x"), ("d", "y", "range sensor y"), ("?", "status", "range sensor status"),
                    ("d", "ux", "range sensor ux"), ("d", "uy", "range sensor uy"),
                    ("d", "range", "range sensor range"), ("s", "object_name", "range sensor object name"))


@dataclass
class TargetSensorEvent(SensorEvent):
    """A target sensor's reading: detector, line of sight, and the target seen (all 0 if none)."""

    x: float
    y: float
    status: bool
    ux: float
    uy: float
    x_detection: float
    y_detection: float
    range: float
    bearing: float
    target_name: str

    code = codes.EVT_TARGET_SENSOR
    record = Record(("d", "x", "target sensor x"), ("d", "y", "target sensor y"),
                    ("?", "status", "target sensor status"), ("d", "ux", "target sensor ux"),
                    ("d", "uy", "target sensor uy"), ("d", "x_detection", "target sensor xDetection"),
                    ("d", "y_detection", "target sensor yDetection"), ("d", "range", "target sensor range"),
                    ("d", "bearing", "target sensor bearing"), ("s", "target_name", "target sensor target name"))


@dataclass
class TimeoutEvent(Event):
    """A timeout fell due; ``timeout_index`` is what the request's method returned."""

    timeout_index: int

    code = codes.EVT_TIMEOUT
    record = Record(("i", "timeout_index", "timeout index"))


@dataclass
class MotionStartedEvent(Event):
    """A motion started: the requested velocities, its planned duration and the start pose."""

    linear_velocity: float
    rotational_velocity: float
    duration: float
    x: float
    y: float
    orientation: float

    code = codes.EVT_MOTION_STARTED
    record = Record(("d", "linear_velocity", "motion started linear velocity"),
                    ("d", "rotational_velocity", "motion started rotational velocity"),
                    ("d", "duration", "motion started duration"), ("d", "x", "motion started x"),
                    ("d", "y", "motion started y"), ("d", "orientation", "motion started orientation"))


@dataclass
class MotionHaltedEvent(Event):
    """A motion ended: on completion (0), on request (1) or in a collision (2)."""

    cause_of_halt: int
    x: float
    y: float
    orientation: float
    duration: float

    HALTED_ON_COMPLETION: ClassVar[int] = 0
    HALTED_ON_REQUEST: ClassVar[int] = 1
    HALTED_ON_COLLISION: ClassVar[int] = 2

    code = codes.EVT_MOTION_HALTED
    record = Record(("i", "cause_of_halt", "motion halted cause"), ("d", "x", "motion halted x"),
                    ("d", "y", "motion halted y"), ("d", "orientation", "motion halted orientation"),
                    ("d", "duration", "motion halted duration"))

    @property
    def why_halted(self) -> str:
        """"completion", "request", "collision", or "internal error" for an unknown cause."""
        return {0: "completion", 1: "request", 2: "collision"}.get(self.cause_of_halt, "internal error")


@dataclass
class PlacementEvent(Event):
    """Whether the robot was put down, under which name and where (a zero pose if not)."""

    valid: bool
    name: str
    x: float
    y: float
    orientation: float

    code = codes.EVT_PLACEMENT
    record = Record(("?", "valid", "placement valid"), ("s", "name", "placement name"), ("d", "x", "placement x"),
                    ("d", "y", "placement y"), ("d", "orientation", "placement orientation"))


@dataclass
class TargetSelectionEvent(Event):
    """A target's selection state after a selection request touched it (status first on the wire)."""

    status: bool
    target_name: str

    code = codes.EVT_TARGET_SELECTION
    record = Record(("?", "status", "target selection status"), ("s", "target_name", "target selection name"))


@dataclass
class PlanEvent(Event):
    """The floor plan, or None if the server has none. The simulator stamps it with time 0."""

    plan: Optional[Plan]

    code = codes.EVT_PLAN

    @classmethod
    def _read(cls, r: Reader, sim_time: float, index: int) -> "Event":
        return cls(sim_time, read_plan(r))

    def _write(self, w: Writer) -> None:
        write_plan(w, self.plan)


@dataclass
class PaintSensorEvent(SensorEvent):
    """A paint sensor's reading: detector point, whether it is on paint it senses, and the region."""

    x: float
    y: float
    status: bool
    region: int

    code = codes.EVT_PAINT_SENSOR
    record = Record(("d", "x", "paint sensor x"), ("d", "y", "paint sensor y"), ("?", "status", "paint sensor status"),
                    ("i", "region", "paint sensor region"))


@dataclass
class HeartbeatEvent(Event):
    """One beat of a heartbeat request; beats are numbered 1, 2, 3, ... per request."""

    sequence: int

    code = codes.EVT_HEARTBEAT
    record = Record(("i", "sequence", "heartbeat sequence"))


@dataclass
class EncoderStatusEvent(Event):
    """One encoder's state, answering an encoder-status request (the encoder id is the wheel's id)."""

    request_index: int
    encoder_id: int
    accumulator: int
    absolute_accumulator: int
    quadrature: int
    interval: int
    angle: float
    clear_on_report: bool

    code = codes.EVT_ENCODER_STATUS
    record = Record(("i", "request_index", "encoder request index"), ("i", "encoder_id", "encoder id"),
                    ("i", "accumulator", "encoder accumulator"),
                    ("i", "absolute_accumulator", "encoder absolute accumulator"),
                    ("i", "quadrature", "encoder quadrature"), ("i", "interval", "encoder interval"),
                    ("d", "angle", "encoder angle"), ("?", "clear_on_report", "encoder clear on report"))


#: The event class for each event code.
EVENT_TYPES: Dict[int, Type[Event]] = {cls.code: cls for cls in (
    ContactSensorEvent, MouseClickEvent, PositionEvent, RangeSensorEvent, TargetSensorEvent, TimeoutEvent,
    MotionStartedEvent, MotionHaltedEvent, PlacementEvent, TargetSelectionEvent, PlanEvent, PaintSensorEvent,
    HeartbeatEvent, EncoderStatusEvent)}


def read_event(r: Reader) -> Tuple[Event, int]:
    """Reads everything after an EVENT header; returns the event and its interlock number."""
    code = r.i32("event code")
    if code not in EVENT_TYPES:
        raise ProtocolError("event code", f"unknown code {code}")
    index = r.i32("event index")
    sim_time = r.f64("event simTime")
    interlock = r.i32("event interlock")
    return EVENT_TYPES[code]._read(r, sim_time, index), interlock


def read_event_body(r: Reader, code: int, index: int, sim_time: float) -> Event:
    """Reads an event's own fields once its prefix has been read (and ``code`` checked)."""
    return EVENT_TYPES[code]._read(r, sim_time, index)


def write_event(w: Writer, event: Event, interlock: int = 0) -> None:
    """Appends an event's prefix and fields; the index is the sensor id for sensor events, else 0."""
    w.pack(_PREFIX, event.code, event.index, event.sim_time, interlock)
    event._write(w)


def encode_event(event: Event, interlock: int = 0) -> bytes:
    """The bytes after the header of an EVENT message (what a server sends)."""
    w = Writer()
    write_event(w, event, interlock)
    return w.getvalue()


def decode_event(data: bytes) -> Tuple[Event, int]:
    """Decodes the bytes after an EVENT header; returns the event and its interlock number.

    Raises:
        ProtocolError: naming the field, if the bytes are not exactly one well-formed event.
    """
    return read_exactly(data, read_event, "event", "the event")

