"""Requests: what a client asks of the simulator (docs/protocol.md section 6).

A client normally sends requests with the ``send_...`` methods of :class:`~rp1client.Client`;
the classes here are what those methods encode, what a wheel system's helpers return
(:class:`MotionRequest`, :class:`ActuatorControlRequest`), and what :func:`decode_request` gives a
test server.
"""

import struct
from dataclasses import dataclass, field
from typing import ClassVar, Dict, List, Optional, Tuple, Type

from . import codes
from .errors import ProtocolError
from .wire import Color, Reader, Record, Writer, read_exactly, require_finite_fields

_PREFIX = struct.Struct(">ii")


class Request:
    """Base of all requests (each concrete request is a dataclass)."""

    code: ClassVar[int] = -1
    record: ClassVar[Record] = Record()

    @classmethod
    def _read(cls, r: Reader) -> "Request":
        return cls(**cls.record.read(r))

    def _write(self, w: Writer) -> None:
        self.record.write(w, self)


@dataclass(frozen=True)
class TimeoutRequest(Request):
    """Asks for a timeout event after ``duration`` simulated seconds, echoing ``timeout_index``."""

    duration: float
    timeout_index: int

    code = codes.REQ_TIMEOUT
    record = Record(("d", "duration", "timeout duration"), ("i", "timeout_index", "timeout index"))


@dataclass(frozen=True)
class SubscriptionRequest(Request):
    """Starts (``enable``) or stops the events of one (event code, index); see section 10."""

    event_code: int
    event_index: int
    enable: bool

    code = codes.REQ_SUBSCRIPTION
    record = Record(("i", "event_code", "subscription event code"), ("i", "event_index", "subscription event index"),
                    ("?", "enable", "subscription enable"))


@dataclass(frozen=True)
class SensorStatusRequest(Request):
    """Polls one sensor, by part id."""

    sensor_id: int

    code = codes.REQ_SENSOR_STATUS
    record = Record(("i", "sensor_id", "sensor id"))


@dataclass(frozen=True)
class MotionRequest(Request):
    """Move for ``duration`` seconds at ``linear_velocity`` (m/s, forward) and
    ``rotational_velocity`` (rad/s, counter-clockwise): a line, an arc or a pivot."""

    linear_velocity: float
    rotational_velocity: float
    duration: float

    code = codes.REQ_MOTION
    record = Record(("d", "linear_velocity", "motion linear velocity"),
                    ("d", "rotational_velocity", "motion rotational velocity"), ("d", "duration", "motion duration"))


@dataclass(frozen=True)
class HaltRequest(Request):
    """Stops the motion in progress."""

    code = codes.REQ_HALT


@dataclass(frozen=True)
class PositionRequest(Request):
    """Asks for a position event."""

    code = codes.REQ_POSITION


@dataclass(frozen=True)
class SetPositionRequest(Request):
    """Reserved code 6: no client sends it and the server ignores it; it has no payload."""

    code = codes.REQ_SET_POSITION


@dataclass(frozen=True)
class PlacementRequest(Request):
    """Asks to be put down at the named placement; None or "" for any, "$random" for a free pose.

    On the wire the name is announced twice: an i32 holding its length in UTF-16 units (only zero
    or non-zero matters), then, if that is not zero, the name itself.
    """

    name: Optional[str]

    code = codes.REQ_PLACEMENT

    @classmethod
    def _read(cls, r: Reader) -> "Request":
        flag = r.i32("placement name flag")
        return cls(r.utf("placement name") if flag != 0 else None)

    def _write(self, w: Writer) -> None:
        flag = len(self.name.encode("utf-16-le", "surrogatepass")) // 2 if self.name else 0
        w.i32(flag)
        if flag:
            w.utf(self.name)


@dataclass(frozen=True)
class TargetSelectionRequest(Request):
    """Selects or deselects targets: ``exclusive`` first deselects all, ``random`` picks one,
    the name "*" means every target."""

    random: bool
    name: Optional[str]
    status: bool
    exclusive: bool

    code = codes.REQ_TARGET_SELECTION
    record = Record(("?", "random", "target selection random"), ("s", "name", "target selection name"),
                    ("?", "status", "target selection status"), ("?", "exclusive", "target selection exclusive"))


@dataclass(frozen=True)
class PlanRequest(Request):
    """Asks for the floor plan."""

    code = codes.REQ_PLAN


@dataclass(frozen=True)
class HeartbeatRequest(Request):
    """Asks for a heartbeat event every ``interval`` simulated seconds; 0 cancels."""

    interval: float

    code = codes.REQ_HEARTBEAT
    record = Record(("d", "interval", "heartbeat interval"))


@dataclass(frozen=True)
class PainterChangeRequest(Request):
    """Erases a painter's trail, switches it off, or switches it on with its trailer and colours."""

    painter_id: int
    erasure: bool = False
    activation: bool = False
    trailer_defined: bool = False
    x_trailer: float = 0.0
    y_trailer: float = 0.0
    width: float = 0.0
    colors: Optional[Tuple[Optional[Color], ...]] = None

    code = codes.REQ_PAINTER_CHANGE

    @classmethod
    def _read(cls, r: Reader) -> "Request":
        painter_id = r.i32("painter id")
        if r.boolean("painter erasure"):
            return cls(painter_id, erasure=True)
        if not r.boolean("painter activation"):
            return cls(painter_id)
        defined = r.boolean("painter trailer defined")
        x = r.f64("painter trailer x")
        y = r.f64("painter trailer y")
        width = r.f64("painter trailer width")
        return cls(painter_id, False, True, defined, x, y, width, r.color_array("painter colors"))

    def _write(self, w: Writer) -> None:
        w.i32(self.painter_id).boolean(self.erasure)
        if self.erasure:
            return
        w.boolean(self.activation)
        if self.activation:
            w.boolean(self.trailer_defined).f64(self.x_trailer).f64(self.y_trailer).f64(self.width)
            w.color_array(self.colors)


@dataclass
class ActuatorControlRequest(Request):
    """A command for the wheel system (by part id) with named parameters, used by position.

    Usually made by ``DifferentialSteering.get_control_request_for_wheel_rotation`` or
    ``AckermanSteering.get_control_request_for_wheel_rotation_and_steering_angle``.
    """

    actuator_id: int
    command_id: int
    parameters: List[Tuple[str, float]] = field(default_factory=list)

    HALT: ClassVar[int] = 1
    RESET: ClassVar[int] = 2
    ACTIVATE: ClassVar[int] = 3

    code = codes.REQ_ACTUATOR_CONTROL

    def add_parameter(self, name: str, value: float) -> None:
        """Appends a parameter; the simulator uses the values in this order."""
        self.parameters.append((name, value))

    def get_parameter(self, name: str) -> Optional[float]:
        """The value of the first parameter with this name (ignoring case), or None."""
        key = name.lower()
        return next((v for n, v in self.parameters if n.lower() == key), None)

    @classmethod
    def _read(cls, r: Reader) -> "Request":
        request = cls(r.i32("actuator id"), r.i32("actuator command"))
        for i in range(r.count("actuator parameter count", codes.MAX_ACTUATOR_PARAMETERS)):
            name = r.utf(f"actuator parameter {i} name")
            request.add_parameter(name, r.f64(f"actuator parameter {i} value"))
        return request

    def _write(self, w: Writer) -> None:
        w.i32(self.actuator_id).i32(self.command_id).i32(len(self.parameters))
        for name, value in self.parameters:
            w.utf(name).f64(value)


@dataclass(frozen=True)
class EncoderStatusRequest(Request):
    """Asks for the state of some encoders (wheel part ids); one event per id, echoing the index."""

    request_index: int
    encoder_ids: Tuple[int, ...]
    clear_on_report: bool

    code = codes.REQ_ENCODER_STATUS

    @classmethod
    def _read(cls, r: Reader) -> "Request":
        index = r.i32("encoder request index")
        n = r.count("encoder id count", codes.MAX_ENCODERS)
        ids = tuple(r.i32(f"encoder id {i}") for i in range(n))
        return cls(index, ids, r.boolean("encoder clear on report"))

    def _write(self, w: Writer) -> None:
        w.i32(self.request_index).i32(len(self.encoder_ids))
        for encoder_id in self.encoder_ids:
            w.i32(encoder_id)
        w.boolean(self.clear_on_report)


#: The request class for each request code.
REQUEST_TYPES: Dict[int, Type[Request]] = {cls.code: cls for cls in (
    TimeoutRequest, SubscriptionRequest, SensorStatusRequest, MotionRequest, HaltRequest, PositionRequest,
    SetPositionRequest, PlacementRequest, TargetSelectionRequest, PlanRequest, HeartbeatRequest,
    PainterChangeRequest, ActuatorControlRequest, EncoderStatusRequest)}


def encode_request(request: Request, check_finite: bool = False) -> bytes:
    """The bytes after the header of a REQUEST message: code, index 0, then the payload.

    Raises:
        ValueError: if a string is too long for the wire, or, with ``check_finite``, if a number
            is NaN or infinite (naming the field, as the server would).
    """
    w = Writer().pack(_PREFIX, request.code, 0)
    request._write(w)
    payload = w.getvalue()
    if check_finite and not w.finite:
        require_finite_fields("", payload, read_request)
    return payload


def read_request(r: Reader) -> Request:
    """Reads everything after a REQUEST header."""
    code = r.i32("request code")
    if code not in REQUEST_TYPES:
        raise ProtocolError("request code", f"unknown code {code}")
    r.i32("request index")
    return REQUEST_TYPES[code]._read(r)


def decode_request(data: bytes) -> Request:
    """Decodes the bytes after a REQUEST header, which must hold exactly one request.

    Raises:
        ProtocolError: naming the field, if the bytes are not one well-formed request.
    """
    return read_exactly(data, read_request, "request", "the request")

